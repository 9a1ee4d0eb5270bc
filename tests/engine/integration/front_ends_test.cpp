#include "engine/front_ends_test.hpp"

namespace front_ends_test {
TEST(FrontEnds, CliSessionPythonAndServerAgreeStepByStep) {
  const FrontEndRun session = session_run();
  ASSERT_EQ(session.steps.size(), kActions.size() + 1);
  ASSERT_FALSE(session.action.empty());
  // The utterance moved the posterior (the runs compare something).
  EXPECT_GT(std::abs(session.steps.back()[0] - session.steps[kActions.size() - 1][0]) +
                std::abs(session.steps.back()[1] - session.steps[kActions.size() - 1][1]),
            1e-3);
  expect_same(session, cli_run(), "cli");
  expect_same(session, server_run(), "server");
  expect_same(session, python_run(), "python");
}

}  // namespace front_ends_test
