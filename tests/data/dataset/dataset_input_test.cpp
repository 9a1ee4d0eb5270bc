#include "data/dataset_input_test.hpp"

namespace clips::data {
namespace dataset_input_test {
TEST_F(DatasetInput, DuplicateGoalInVhGoalSetIsRejectedWithFileAndLine) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  fs::path dir = vh_slice();
  auto ds = Dataset::load(dir.string());
  ASSERT_EQ(ds.plans().size(), 2u);
  EXPECT_EQ(ds.plans()[1].observed.utterances.size(), 2u);  // VH plans may have several
  auto set = read(dir / "goals/sets/1.txt");
  write(dir / "goals/sets/1.txt", "\n" + set + "\nstew_chicken\n");
  // The blank first line counts: stew_chicken is at line 5, its copy at line 8.
  EXPECT_THAT(load_error(dir), HasSubstr("goals/sets/1.txt:8:1: goal 'stew_chicken' is listed twice (also at line 5)"));
}

TEST_F(DatasetInput, UnknownVhGoalReportsItsRealLine) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  fs::path dir = vh_slice();
  write(dir / "goals/sets/1.txt", "salad_veggie\n\nno_such_goal\n");
  EXPECT_THAT(load_error(dir), HasSubstr("goals/sets/1.txt:3:1: goal 'no_such_goal' has no file"));
}

TEST_F(DatasetInput, VhGoalDefinitionErrorsNameTheirFile) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  fs::path dir = vh_slice();
  replace(dir / "goals/definitions/stew_chicken.pddl", "(placed onion1 table1)", "(placed onion9 table1)");
  auto ds = Dataset::load(dir.string());
  bool named = false;
  for (auto& p : ds.plans()) {
    const PlanCheck c = validate_plan(ds, p);
    named = named || c.error.find("goals/definitions/stew_chicken.pddl:2:11: unknown object 'onion9'") !=
                         std::string::npos;
  }
  EXPECT_TRUE(named);
}

TEST_F(DatasetInput, EmptyVhUtteranceIsRejectedWithFileAndLine) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  fs::path dir = vh_slice();
  replace(dir / "plans/observed/1.1.stew_chicken.pddl", "; Can you get the wine?", ";");
  EXPECT_THAT(load_error(dir), HasSubstr("plans/observed/1.1.stew_chicken.pddl:8:1: empty utterance"));
}

TEST_F(DatasetInput, EmptyVhObservedPlanIsRejected) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  fs::path dir = vh_slice();
  write(dir / "plans/observed/1.1.stew_chicken.pddl", "");
  EXPECT_THAT(load_error(dir), HasSubstr("plans/observed/1.1.stew_chicken.pddl: observed plan is empty"));
}

TEST_F(DatasetInput, SharedDatasetsStillValidate) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  for (auto [dir, n] : {std::pair{paths::dkg_dataset(), 27u}, std::pair{paths::vh_dataset(), 20u}}) {
    auto ds = Dataset::load(dir);
    auto rep = validate_dataset(ds);
    EXPECT_EQ(rep.results.size(), n) << dir;
    for (auto& r : rep.results) EXPECT_TRUE(r.ok) << r.plan_id << ": " << r.error;
  }
  auto ds = Dataset::load(paths::dkg_dataset());
  EXPECT_TRUE(ds.stimulus("2.1.keys"));
  EXPECT_FALSE(ds.stimulus("demo0.1.keys"));
}

}  // namespace dataset_input_test

}  // namespace clips::data
