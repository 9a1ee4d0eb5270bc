// A decision policy of the library's user (include/clips/policy.hpp): one
// registration, then a session decides by it and sees what it was told.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "clips/clips.hpp"
#include "test_paths.hpp"

namespace policy_test {

std::string examples_dkg() { return clips::paths::examples_dir() + "/doors-keys-gems"; }

clips::Session played(clips::Assistance a) {
  clips::SessionOptions o;
  o.assistance = a;
  o.threads = 1;
  auto s = clips::Session::open_dataset(examples_dkg(), "e1", o);
  s.observe("(left human)");
  s.observe("(wait robot)");
  s.hear("Can you get me the yellow key?");
  s.observe("(left human)");  // the robot is to move
  return s;
}

TEST(Policy, ARegisteredPolicyDecidesASessionFromWhatItSees) {
  std::vector<clips::PolicyView> seen;
  const clips::Assistance idle = clips::register_policy(
      "test_api_idle", "waits, whatever it hears", [&seen](const clips::PolicyView& v) {
        seen.push_back(v);
        return clips::PolicyChoice{v.wait, "the test policy waits"};
      });
  struct Unregister {
    ~Unregister() { clips::unregister_policy("test_api_idle"); }
  } unregister;
  EXPECT_EQ(clips::parse_assistance("test_api_idle"), idle);
  EXPECT_EQ(clips::assistance_help(idle), "waits, whatever it hears");

  auto s = played(idle);
  const clips::AssistDecision d = s.assist();
  ASSERT_EQ(seen.size(), 1u);
  const clips::PolicyView& v = seen.back();
  EXPECT_EQ(d.action, v.wait);
  EXPECT_EQ(d.reason, "the test policy waits");
  EXPECT_GT(v.actions.size(), 1u);
  EXPECT_NE(std::find(v.actions.begin(), v.actions.end(), v.wait), v.actions.end());
  // The posterior's goals as PDDL conditions, with its weights.
  const clips::Posterior p = s.posterior();
  ASSERT_EQ(v.goals.size(), p.goals.size());
  for (size_t i = 0; i < v.goals.size(); ++i) EXPECT_NEAR(v.goal_weights[i], p.goal_probabilities[i], 1e-9);
  EXPECT_EQ(v.goals.front().front(), '(');
  // What the instruction asked for: the yellow key's fetch leads.
  ASSERT_FALSE(v.asked.empty());
  const size_t top = static_cast<size_t>(std::max_element(v.asked_weights.begin(), v.asked_weights.end()) -
                                         v.asked_weights.begin());
  EXPECT_NE(v.asked[top].find("key"), std::string::npos) << v.asked[top];
  EXPECT_NE(played(clips::Assistance::QMdp).assist().action, d.action);  // Q_MDP moves

  EXPECT_THROW(clips::register_policy("test_api_idle", "again", [](const clips::PolicyView& w) {
                 return clips::PolicyChoice{w.wait, ""};
               }),
               clips::InputError);
  EXPECT_THROW(clips::register_policy("qmdp_offline", "a bench name", [](const clips::PolicyView& w) {
                 return clips::PolicyChoice{w.wait, ""};
               }),
               clips::InputError);
  EXPECT_THROW(clips::register_policy("a/b", "", [](const clips::PolicyView& w) {
                 return clips::PolicyChoice{w.wait, ""};
               }),
               clips::InputError);
  EXPECT_THROW(clips::unregister_policy("qmdp"), clips::InputError);
}

TEST(Policy, AChoiceThatIsNoActionOrAThrowIsAnInputErrorNamingThePolicy) {
  const clips::Assistance flies = clips::register_policy(
      "test_api_flies", "", [](const clips::PolicyView&) { return clips::PolicyChoice{"(fly robot)", ""}; });
  const clips::Assistance throws = clips::register_policy(
      "test_api_throws", "", [](const clips::PolicyView&) -> clips::PolicyChoice { throw std::runtime_error("no"); });
  struct Unregister {
    ~Unregister() {
      clips::unregister_policy("test_api_flies");
      clips::unregister_policy("test_api_throws");
    }
  } unregister;
  auto a = played(flies);
  try {
    a.assist();
    ADD_FAILURE() << "a non-action was taken";
  } catch (const clips::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'test_api_flies' returned '(fly robot)', which is not an applicable action"),
              std::string::npos)
        << e.what();
  }
  auto b = played(throws);
  try {
    b.assist();
    ADD_FAILURE() << "the exception was lost";
  } catch (const clips::InputError& e) {
    EXPECT_STREQ(e.what(), "assistance policy 'test_api_throws' raised no");
  }
  // The session is still usable.
  EXPECT_EQ(b.t(), 3);
}

}  // namespace policy_test
