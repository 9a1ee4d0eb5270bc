#include "api/session_test.hpp"

namespace session_test {
TEST(Session, ReplayMatchesClipsInferOnThePapersDataset) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset at " << clips::paths::dkg_dataset();
  check_replay_matches_cli(clips::paths::dkg_dataset(), "2.1.keys");
}

}  // namespace session_test
