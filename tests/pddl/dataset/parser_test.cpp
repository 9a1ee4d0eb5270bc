#include "pddl/parser_test.hpp"

TEST(Parser, ReadsBothSharedDatasetDomains) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not present";
  Domain dkg = load_domain(paths::dkg_dataset() + "/domain.pddl");
  EXPECT_EQ(dkg.actions.size(), 8u);
  Domain vh = load_domain(paths::vh_dataset() + "/domain.pddl");
  EXPECT_EQ(vh.name, "virtual-home");
  EXPECT_GE(vh.find_action("grab"), 0);
}
