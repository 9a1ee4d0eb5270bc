// The session engine's per-call limits (src/engine): a wall-clock limit and a
// cancellation each stop a call, the engine is left exactly as it was, and
// the next call gives what it would have given without the stopped one.
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "engine/engine.hpp"
#include "engine/json.hpp"
#include "language/listener.hpp"
#include "test_paths.hpp"

namespace clips::engine {
namespace {

std::string examples_dkg() { return paths::examples_dir() + "/doors-keys-gems"; }

// The embedded model, which raises the cancellation flag whenever it is
// asked to score: a cancellation that arrives in the middle of a call, always.
class CancellingModel : public lm::LanguageModel {
 public:
  explicit CancellingModel(std::atomic<bool>& flag) : inner_(language::make_language_model("embedded")), flag_(flag) {}
  std::string name() const override { return "cancelling"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    flag_ = true;
    return inner_->score(batch);
  }

 private:
  std::shared_ptr<lm::LanguageModel> inner_;
  std::atomic<bool>& flag_;
};

// The embedded model, which holds every scoring call until released and says
// when the first one came: a call that is surely running while another
// thread acts on it.
class HeldModel : public lm::LanguageModel {
 public:
  HeldModel() : inner_(language::make_language_model("embedded")) {}
  std::string name() const override { return "held"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    {
      std::unique_lock lock(mutex_);
      entered_ = true;
      changed_.notify_all();
      changed_.wait(lock, [this] { return released_; });
    }
    return inner_->score(batch);
  }
  void wait_until_scoring() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return entered_; });
  }
  void release() {
    std::lock_guard lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }

 private:
  std::shared_ptr<lm::LanguageModel> inner_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool entered_ = false, released_ = false;
};

Engine opened(std::shared_ptr<lm::LanguageModel> lm = nullptr) {
  return Engine(dataset_problem(examples_dkg(), "e1"), SessionOptions{}, std::move(lm));
}

// Everything a caller can read of an engine, as JSON.
nlohmann::json snapshot(const Engine& e) {
  nlohmann::json j;
  j["t"] = e.t();
  j["posterior"] = to_json(e.posterior(), e.method());
  j["lang"] = to_json(e.posterior(Method::LanguageOnly), Method::LanguageOnly);
  j["action"] = to_json(e.posterior(Method::ActionOnly), Method::ActionOnly);
  j["trace"] = nlohmann::json::array();
  for (const auto& s : e.trace()) {
    auto sj = to_json(s, e.method());
    sj.erase("seconds");
    j["trace"].push_back(sj);
  }
  j["events"] = e.events().size();
  j["history"] = e.history().size();
  j["state"] = e.pack().describe_state(e.task(), e.state());
  j["refinements"] = e.refinements();
  return j;
}

TEST(EngineLimits, ATimeLimitStopsACallAndLeavesTheEngineUnchanged) {
  Engine e = opened();
  e.observe("(left human)");
  const auto before = snapshot(e);
  CallLimits none_left;
  none_left.seconds = 0;  // already over when the call starts: every search stops at once
  EXPECT_THROW(e.observe("(wait robot)", none_left), TimeLimitError);
  EXPECT_EQ(snapshot(e), before);
  EXPECT_THROW(e.hear("Can you get me the yellow key?", none_left), TimeLimitError);
  EXPECT_EQ(snapshot(e), before);
  EXPECT_THROW(e.undo(none_left), TimeLimitError);
  EXPECT_EQ(snapshot(e), before);

  // The following calls work, and give what an engine that never saw the
  // stopped ones gives.
  Engine reference = opened();
  reference.observe("(left human)");
  e.observe("(wait robot)");
  reference.observe("(wait robot)");
  EXPECT_EQ(snapshot(e), snapshot(reference));
  e.observe("(left human)");
  EXPECT_THROW(e.assist(none_left), TimeLimitError);
  reference.observe("(left human)");
  EXPECT_EQ(snapshot(e), snapshot(reference));
  EXPECT_EQ(to_json(e.assist()), to_json(reference.assist()));
}

TEST(EngineLimits, ACancelledCallLeavesTheEngineUnchanged) {
  Engine e = opened();
  e.observe("(left human)");
  const auto before = snapshot(e);
  std::atomic<bool> cancel{true};
  CallLimits flag;
  flag.cancel = &cancel;
  EXPECT_THROW(e.observe("(wait robot)", flag), CancelledError);
  EXPECT_EQ(snapshot(e), before);
  EXPECT_THROW(e.assist(flag), CancelledError);
  EXPECT_THROW(e.undo(flag), CancelledError);
  EXPECT_EQ(snapshot(e), before);
  cancel = false;
  const Step& s = e.observe("(wait robot)", flag);  // a flag that stays down: the call runs
  EXPECT_EQ(s.t, 2);
}

TEST(EngineLimits, AnotherThreadCancelsARunningCall) {
  // A controller thread raises the flag while the call is in the middle of
  // scoring the utterance (the model holds it there until then): the call
  // throws CancelledError, the engine is as it was, the next call works.
  std::atomic<bool> cancel{false};
  auto model = std::make_shared<HeldModel>();
  Engine e = opened(model);
  e.observe("(left human)");
  e.observe("(wait robot)");
  const auto before = snapshot(e);
  std::thread controller([&] {
    model->wait_until_scoring();
    cancel = true;
    model->release();
  });
  CallLimits limits;
  limits.cancel = &cancel;
  EXPECT_THROW(e.hear("Can you get me the yellow key?", limits), CancelledError);
  controller.join();
  EXPECT_EQ(snapshot(e), before);
  e.hear("Can you get me the yellow key?");  // the model lets it through now
  Engine reference = opened();
  reference.observe("(left human)");
  reference.observe("(wait robot)");
  reference.hear("Can you get me the yellow key?");
  EXPECT_EQ(snapshot(e), snapshot(reference));
}

TEST(EngineLimits, ACancellationInTheMiddleOfACallUndoesIt) {
  // The model requests the stop while the utterance is being scored: the
  // belief has already been refined and partly updated, and all of it is
  // dropped.
  std::atomic<bool> cancel{false};
  auto model = std::make_shared<CancellingModel>(cancel);
  Engine e = opened(model);
  e.observe("(left human)");
  e.observe("(wait robot)");
  const auto before = snapshot(e);
  CallLimits limits;
  limits.cancel = &cancel;
  EXPECT_THROW(e.hear("Can you get me the yellow key?", limits), CancelledError);
  EXPECT_TRUE(cancel.load());
  EXPECT_EQ(snapshot(e), before);
  // The same call without the flag goes through, as on an engine that never
  // saw the cancelled one.
  e.hear("Can you get me the yellow key?");
  Engine reference = opened(model);
  reference.observe("(left human)");
  reference.observe("(wait robot)");
  reference.hear("Can you get me the yellow key?");
  EXPECT_EQ(snapshot(e), snapshot(reference));
}

TEST(EngineLimits, ANegativeOrNanLimitIsAnInputError) {
  Engine e = opened();
  CallLimits bad;
  bad.seconds = -1;
  EXPECT_THROW(e.observe("(left human)", bad), InputError);
  bad.seconds = std::nan("");
  EXPECT_THROW(e.observe("(left human)", bad), InputError);
  EXPECT_EQ(e.t(), 0);
}

TEST(EngineMethods, OneNameTableReadsEverySpelling) {
  EXPECT_EQ(parse_method("clips"), Method::Clips);
  EXPECT_EQ(parse_method("both"), Method::Clips);
  EXPECT_EQ(parse_method("lang_only"), Method::LanguageOnly);
  EXPECT_EQ(parse_method("utterance"), Method::LanguageOnly);
  EXPECT_EQ(parse_method("language"), Method::LanguageOnly);
  EXPECT_EQ(parse_method("action_only"), Method::ActionOnly);
  EXPECT_EQ(parse_method("action"), Method::ActionOnly);
  EXPECT_EQ(parse_method("literal"), Method::Literal);
  for (const auto& n : method_names()) EXPECT_EQ(method_name(parse_method(n)), n);
  try {
    parse_method("telepathy");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown method 'telepathy'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("lang_only"), std::string::npos);
  }
}

TEST(EngineUndo, UndoTakesBackTheHumansLatestMoveOrInstructionAndWhatFollowed) {
  Engine e = opened();
  EXPECT_FALSE(e.undo());
  const auto at_start = snapshot(e);
  e.observe("(left human)");
  e.observe("(wait robot)");
  const auto after_two = snapshot(e);
  e.observe("(left human)");
  const auto after_three = snapshot(e);
  e.hear("Can you get me the yellow key?");
  // The instruction goes alone; then the last human action.
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(snapshot(e), after_three);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(snapshot(e), after_two);
  // Then the first one, with the robot's wait after it.
  ASSERT_TRUE(e.undo());
  auto start = snapshot(e);
  EXPECT_EQ(start, at_start);
  e.reset();
  EXPECT_EQ(e.t(), 0);
  EXPECT_TRUE(e.events().empty());
  EXPECT_FALSE(e.reached_goal().has_value());
  for (int g = 0; g < static_cast<int>(e.goal_labels().size()); ++g) EXPECT_FALSE(e.goal_holds(g));
  EXPECT_THROW(e.goal_holds(99), InputError);
}

}  // namespace
}  // namespace clips::engine

namespace clips::engine {
namespace {

TEST(EngineOpeners, AGeneratedProblemPlays) {
  domains::GenerateParams params;
  params.counts = {{"gem", 3}, {"key", 2}, {"door", 1}};
  params.problem_name = "drawn";
  const std::string dkg = paths::source_dir() + "/data/domains/doors-keys-gems";
  Engine e(generated_problem(dkg, params, 7), SessionOptions{});
  EXPECT_EQ(e.problem().problem, "drawn");
  EXPECT_EQ(e.goal_labels(), (std::vector<std::string>{"gem1", "gem2", "gem3"}));
  // The same seed draws the same problem.
  Engine again(generated_problem(dkg, params, 7), SessionOptions{});
  EXPECT_EQ(e.pack().describe_state(e.task(), e.state()), again.pack().describe_state(again.task(), again.state()));
  ASSERT_FALSE(e.assistant_turn());
  const auto acts = e.applicable_actions();
  ASSERT_FALSE(acts.empty());
  const Step& s = e.observe(acts.front().action);
  EXPECT_EQ(s.t, 1);
  double sum = 0;
  for (double p : s.posterior.goal_probabilities) sum += p;
  EXPECT_NEAR(sum, 1.0, 1e-9);
  params.counts = {{"gem", 0}};
  EXPECT_THROW(generated_problem(dkg, params, 7), InputError);
}

}  // namespace
}  // namespace clips::engine
