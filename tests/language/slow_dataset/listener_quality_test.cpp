// Literal-listener quality on the visible mDKG dataset with the default
// (embedded) language model: does the most probable command describe what the
// completed plan actually does? Prints every figure and every miss.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <regex>

#include "domains/dkg/dkg_world.hpp"
#include "language/dataset_fixture.hpp"
#include "language/listener.hpp"

namespace clips::language {
namespace {

struct Trial {
  std::string plan, utterance;
};

struct Tally {
  int total = 0, hits = 0;
  std::vector<std::string> misses;
  double rate() const { return total == 0 ? 0.0 : static_cast<double>(hits) / total; }
};

bool names_a_colour(const std::string& utterance) {
  static const std::regex colour(R"(\b(red|yellow|blue|green)\b)", std::regex::icase);
  return std::regex_search(utterance, colour);
}

class ListenerQuality : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!paths::have_shared_dataset()) return;
    data_ = new testing::DatasetFixture(paths::dkg_dataset());
    lm_ = make_language_model("embedded");
    setup_ = new LiteralListenerSetup(literal_listener_setup("doors-keys-gems"));
  }
  static void TearDownTestSuite() {
    delete data_;
    delete setup_;
    lm_.reset();
    data_ = nullptr;
    setup_ = nullptr;
  }
  void SetUp() override {
    if (data_ == nullptr) GTEST_SKIP() << "no dataset at " << paths::dkg_dataset();
  }

  // Runs the listener and records a hit when the top command is fulfilled by
  // the plan's completion.
  static void judge(const testing::PlanData& p, const std::string& utterance, Tally& tally) {
    const auto result = literal_listener(*p.task, p.s_T, utterance, *setup_, *lm_);
    ASSERT_FALSE(result.commands.empty());
    const auto& top = result.commands.front();
    ++tally.total;
    if (completed_plan_satisfies(*p.task, p.observed, p.completed, top.command, setup_->config)) {
      ++tally.hits;
      return;
    }
    // The best-ranked command the plan does fulfil, to say what should have won.
    std::string wanted = "(none of the candidates)";
    for (size_t i = 1; i < result.commands.size(); ++i)
      if (completed_plan_satisfies(*p.task, p.observed, p.completed, result.commands[i].command, setup_->config)) {
        wanted = result.commands[i].command.display_form() + " (rank " + std::to_string(i + 1) +
                 ", p=" + std::to_string(result.commands[i].prob) + ")";
        break;
      }
    tally.misses.push_back(p.id + ": \"" + utterance + "\" -> " + top.command.display_form() +
                           " (p=" + std::to_string(top.prob) + "); should be " + wanted);
  }

  static void report(const char* what, const Tally& t) {
    std::printf("[listener] %s: %d/%d = %.3f\n", what, t.hits, t.total, t.rate());
    for (const auto& m : t.misses) std::printf("[listener]   miss %s\n", m.c_str());
  }

  static testing::DatasetFixture* data_;
  static std::shared_ptr<lm::LanguageModel> lm_;
  static LiteralListenerSetup* setup_;
};

testing::DatasetFixture* ListenerQuality::data_ = nullptr;
std::shared_ptr<lm::LanguageModel> ListenerQuality::lm_;
LiteralListenerSetup* ListenerQuality::setup_ = nullptr;

TEST_F(ListenerQuality, LiteralUtterances) {
  Tally all, colour;
  for (const auto& p : data_->plans()) {
    if (p.literal_utterance.empty()) continue;  // demo plans
    Tally one;
    judge(p, p.literal_utterance, one);
    all.total += one.total;
    all.hits += one.hits;
    all.misses.insert(all.misses.end(), one.misses.begin(), one.misses.end());
    if (names_a_colour(p.literal_utterance)) {
      colour.total += one.total;
      colour.hits += one.hits;
      colour.misses.insert(colour.misses.end(), one.misses.begin(), one.misses.end());
    }
  }
  report("literal utterances, all", all);
  report("literal utterances naming a colour", colour);
  ASSERT_GT(colour.total, 0);
  EXPECT_GE(colour.rate(), 0.9);
}

// What the completed plan has the robot do, read off the plan itself: the
// first door the robot unlocks if any ("door" request), else the first key it
// hands over or picks up ("key" request), with the focal object's colour.
struct TrueRequest {
  bool door = false;
  std::string colour;
};

std::optional<TrueRequest> true_request(const testing::PlanData& p) {
  const domains::dkg::DkgWorld world(*p.task);
  const auto sim = pddl::simulate(*p.task, p.s_T, p.completed);
  std::optional<TrueRequest> key;
  for (pddl::ActionId a : sim.actions) {
    const auto& act = p.task->action(a);
    const std::string& schema = p.task->domain().actions[act.schema].name;
    if (act.args.empty() || act.args[0] != world.robot()) continue;
    if (schema == "unlock") return TrueRequest{true, world.color(act.args[2])};
    if ((schema == "pickup" || schema == "handover") && !key) key = TrueRequest{false, world.color(act.args.back())};
  }
  return key;
}

// Paraphrases written for this test (none is a few-shot or dataset utterance).
const std::vector<std::string> kKeyTemplates = {
    "Could you grab me a {} key?",
    "Fetch the {} key please.",
    "Look for a {} key.",
    "Bring me that {} key.",
    "I need a key for this {} door.",
};
const std::vector<std::string> kDoorTemplates = {
    "Get the {} door.",
    "Please open that {} door.",
    "Could you unlock the {} door for me?",
    "Open up the {} door over there.",
};

std::string fill(const std::string& tmpl, const std::string& colour) {
  std::string out = tmpl;
  out.replace(out.find("{}"), 2, colour);
  return out;
}

TEST_F(ListenerQuality, OwnParaphrases) {
  Tally tally;
  for (const auto& p : data_->plans()) {
    if (p.literal_utterance.empty()) continue;
    const auto req = true_request(p);
    if (!req || req->colour.empty()) continue;
    for (const auto& tmpl : req->door ? kDoorTemplates : kKeyTemplates) judge(p, fill(tmpl, req->colour), tally);
  }
  report("own paraphrases", tally);
  ASSERT_GT(tally.total, 0);
  EXPECT_GE(tally.rate(), 0.9);
}

}  // namespace
}  // namespace clips::language
