// A decision policy registered for the live sessions (engine/policies.hpp) is
// a bench method as well: the bench's episodes call its decide() at each of
// the assistant's turns, as the session engine does.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <string>

#include <nlohmann/json.hpp>

#include "data/dataset.hpp"
#include "engine/policies.hpp"
#include "eval/experiment.hpp"
#include "eval/methods.hpp"
#include "language/listener.hpp"
#include "eval/support.hpp"

namespace clips::eval {
namespace {

std::string plan_text(const MethodResult& r) {
  std::string out;
  for (const auto& a : r.plan) out += a + " ";
  return out;
}

TEST(RegisteredPolicy, TheBenchsEpisodesDecideByIt) {
  std::atomic<int> calls{0};
  std::string wait;  // the assistant's no-op, by its name in the plan
  engine::register_assistance({static_cast<Assistance>(97), "test_idle", "the assistant only ever waits",
                               [&calls, &wait](const engine::DecisionInput& in) {
                                 ++calls;
                                 assist::Decision d;
                                 d.action = in.setup.turns().noop(*in.setup.task, in.setup.assistant);
                                 wait = in.setup.task->action_name(d.action);
                                 d.candidates = {d.action};
                                 d.values = {0.0};
                                 d.reason = "the test policy waits";
                                 return d;
                               }});
  struct Unregister {
    ~Unregister() { engine::unregister_assistance("test_idle"); }
  } unregister;

  const data::Dataset ds = data::Dataset::load(testing::examples_dkg());
  const auto lm = language::make_language_model("embedded", {});
  ExperimentOptions o;
  o.methods = {"clips", "clips/test_idle"};
  const PlanOutcome out = evaluate_plan(ds, ds.plan("e1.1.keys"), *lm, o);
  ASSERT_EQ(out.error, "");
  const MethodResult* qmdp = out.find("clips");
  const MethodResult* idle = out.find("clips/test_idle");
  ASSERT_NE(qmdp, nullptr);
  ASSERT_NE(idle, nullptr);
  ASSERT_EQ(idle->error, "");
  EXPECT_GT(calls.load(), 0);
  // Every assistant turn of the episode was the registered policy's: its
  // no-op, once per call. Q_MDP's assistant fetches the key the human needs;
  // the registered policy's never picks anything up.
  EXPECT_EQ(std::count(idle->plan.begin(), idle->plan.end(), wait), calls.load()) << plan_text(*idle);
  EXPECT_FALSE(qmdp->options.empty());
  EXPECT_TRUE(idle->options.empty());
  EXPECT_NE(idle->plan, qmdp->plan);
}

// `assist --problem` decides by the policy --assist names: pi-bar's values
// are the probabilities that the mixture takes each action, Q_MDP's are not.
TEST(RegisteredPolicy, AssistProblemDecidesByTheNamedPolicy) {
  auto decide = [](const std::string& policy) {
    const auto r = testing::run(testing::clips_binary() + " assist --dataset " + testing::examples_dkg() +
                                " --problem e1 --actions '(left human)' --utterance 'Can you get me the yellow key?'" +
                                " --json --assist " + policy);
    EXPECT_EQ(r.status, 0) << r.out;
    return nlohmann::json::parse(r.out.substr(r.out.find('{')))["decision"];
  };
  const auto values = [](const nlohmann::json& d) {
    double sum = 0;
    for (const auto& c : d["candidates"]) sum += c["value"].get<double>();
    return sum;
  };
  EXPECT_NEAR(values(decide("pibar")), 1.0, 1e-9);
  EXPECT_LT(values(decide("qmdp_offline")), 0.0);  // costs: negative values
}

}  // namespace
}  // namespace clips::eval
