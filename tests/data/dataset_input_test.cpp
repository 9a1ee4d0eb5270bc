#include "data/dataset_input_test.hpp"

namespace clips::data {
namespace dataset_input_test {
TEST_F(DatasetInput, ExampleDatasetLoadsAndValidates) {
  auto ds = Dataset::load(dkg_copy().string());
  ASSERT_EQ(ds.plans().size(), 4u);
  auto rep = validate_dataset(ds);
  for (auto& r : rep.results) EXPECT_TRUE(r.ok) << r.plan_id << ": " << r.error;
  EXPECT_EQ(ds.plans()[0].literal_utterance, "Can you get me the yellow key?");
}

TEST_F(DatasetInput, GemWithoutPositionIsRejectedNamingTheProblemFile) {
  fs::path dir = dkg_copy();
  replace(dir / "problems/e1.pddl", "(= (xloc gem1) 1) (= (yloc gem1) 1)", "");
  std::string err = task_error(dir, "e1");
  EXPECT_THAT(err, HasSubstr("problems/e1.pddl: gem1 has no position on the 9x5 grid"));
  // validate reports it for the plans on that map, and the other map is fine.
  auto ds = Dataset::load(dir.string());
  auto rep = validate_dataset(ds);
  EXPECT_EQ(rep.failed, 2);
  for (auto& r : rep.results) {
    if (r.plan_id.rfind("e1.", 0) == 0) {
      EXPECT_THAT(r.error, HasSubstr("gem1 has no position")) << r.plan_id;
    }
  }
  EXPECT_NO_THROW(ds.task("e2"));
}

TEST_F(DatasetInput, GemOffTheGridIsRejected) {
  fs::path dir = dkg_copy();
  replace(dir / "problems/e1.pddl", "(= (xloc gem1) 1) (= (yloc gem1) 1)", "(= (xloc gem1) 50) (= (yloc gem1) 60)");
  EXPECT_THAT(task_error(dir, "e1"), HasSubstr("problems/e1.pddl: gem1 is outside the 9x5 grid at (50, 60)"));
}

TEST_F(DatasetInput, KeyOffTheGridIsRejected) {
  fs::path dir = dkg_copy();
  replace(dir / "problems/e1.pddl", "(= (xloc key2) 9)", "(= (xloc key2) 10)");
  EXPECT_THAT(task_error(dir, "e1"), HasSubstr("problems/e1.pddl: key2 is outside the 9x5 grid at (10, 3)"));
}

TEST_F(DatasetInput, DoorAndAgentOffTheGridNameTheProblemFile) {
  fs::path dir = dkg_copy();
  replace(dir / "problems/e1.pddl", "(= (xloc door1) 3)", "(= (xloc door1) 30)");
  EXPECT_THAT(task_error(dir, "e1"), HasSubstr("problems/e1.pddl: door1 is outside the 9x5 grid"));
  dir = dkg_copy();
  replace(dir / "problems/e1.pddl", "(= (xloc human) 5) (= (yloc human) 3)", "");
  EXPECT_THAT(task_error(dir, "e1"), HasSubstr("problems/e1.pddl: human has no position on the 9x5 grid"));
}

TEST_F(DatasetInput, HeldItemNeedsNoPosition) {
  fs::path dir = dkg_copy();
  replace(dir / "problems/e2.pddl", "(= (xloc key1) 5) (= (yloc key1) 1)", "(has robot key1)");
  EXPECT_EQ(task_error(dir, "e2"), "<grounded without error>");
}

TEST_F(DatasetInput, GoalLabelThatIsNotUtf8IsRefusedWithFileAndLine) {
  fs::path dir = kitchen_copy();
  const std::string label = "kuchen\xfc";
  write(dir / "goals/definitions" / (label + ".pddl"), "(made cake)\n");
  write(dir / "goals/sets/1.txt", "pancakes\ncustard\nomelette\ncake\n" + label + "\n");
  const std::string error = load_error(dir);
  EXPECT_THAT(error, HasSubstr("goals/sets/1.txt:5:1: goal label is not valid UTF-8 (byte 0xfc at offset 6)"));
  EXPECT_EQ(error.find('\xfc'), std::string::npos) << "the bad byte is echoed";
  // The folder reader (a problem outside a loaded dataset) says the same.
  try {
    folder_goal_set(dir.string(), "1");
    ADD_FAILURE() << "folder_goal_set accepted the label";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("goals/sets/1.txt:5:1: goal label is not valid UTF-8"));
  }
}

TEST_F(DatasetInput, GoalLabelWithAPathIsRefused) {
  fs::path dir = kitchen_copy();
  // domain.pddl exists two folders up from goals/definitions/: never read as a goal.
  write(dir / "goals/sets/1.txt", "pancakes\n../../domain\n");
  EXPECT_THAT(load_error(dir),
              HasSubstr("goals/sets/1.txt:2:1: goal label '../../domain' must be a file name: no '/' or '\\', no leading '.'"));
  try {
    folder_goal_set(dir.string(), "1");
    ADD_FAILURE() << "folder_goal_set accepted the label";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("goals/sets/1.txt:2:1: goal label '../../domain' must be a file name"));
  }
  // A plain label still loads.
  write(dir / "goals/sets/1.txt", "pancakes\ncustard\n");
  EXPECT_EQ(folder_goal_set(dir.string(), "1").size(), 2u);
}

TEST_F(DatasetInput, MultiLineUtteranceFileIsRejected) {
  fs::path dir = dkg_copy();
  write(dir / "utterances/literal/e1.1.keys.txt", "Can you get me\nthe yellow key?\n");
  EXPECT_THAT(load_error(dir), HasSubstr("utterances/literal/e1.1.keys.txt:2:1: an utterance file holds exactly one"));
  dir = dkg_copy();
  write(dir / "utterances/pragmatic/e1.1.keys.txt", "Can you get me the yellow key?\n\nAnd the gem.\n");
  EXPECT_THAT(load_error(dir), HasSubstr("utterances/pragmatic/e1.1.keys.txt:3:1"));
}

TEST_F(DatasetInput, EmptyUtteranceFileIsRejectedButBlankLinesAroundOneAreFine) {
  fs::path dir = dkg_copy();
  write(dir / "utterances/literal/e1.1.keys.txt", "\n  \n");
  EXPECT_THAT(load_error(dir), HasSubstr("utterances/literal/e1.1.keys.txt is empty"));
  dir = dkg_copy();
  write(dir / "utterances/literal/e1.1.keys.txt", "\n  Can you get me the key?  \r\n\n");
  auto ds = Dataset::load(dir.string());
  EXPECT_EQ(ds.plan("e1.1.keys").literal_utterance, "Can you get me the key?");
}

TEST_F(DatasetInput, SecondCommentInDkgObservedPlanIsRejectedAtItsLine) {
  fs::path dir = dkg_copy();
  write(dir / "plans/observed/e1.1.keys.pddl",
        "; hello\n(left human)\n\n  ; c\n(wait robot)\n(left human)\n(wait robot)\n; Can you get me the yellow key?\n");
  EXPECT_THAT(load_error(dir), HasSubstr("plans/observed/e1.1.keys.pddl:4:3: a second utterance"));
  EXPECT_THAT(load_error(dir), HasSubstr("(the first is at line 1)"));
}

TEST_F(DatasetInput, EmptyDkgObservedPlanIsRejected) {
  fs::path dir = dkg_copy();
  write(dir / "plans/observed/e1.1.keys.pddl", "\n\n");
  EXPECT_THAT(load_error(dir), HasSubstr("plans/observed/e1.1.keys.pddl: observed plan is empty"));
  dir = dkg_copy();
}

TEST_F(DatasetInput, DkgObservedPlanWithoutAnUtteranceLoadsForActionOnlyInference) {
  fs::path dir = dkg_copy();
  write(dir / "plans/observed/e1.1.keys.pddl", "(left human)\n(wait robot)\n");
  auto ds = Dataset::load(dir.string());
  EXPECT_EQ(ds.plan("e1.1.keys").observed.actions.size(), 2u);
  EXPECT_TRUE(ds.plan("e1.1.keys").observed.utterances.empty());
}

TEST_F(DatasetInput, DkgObservedPlanWithOnlyAnUtteranceIsLegal) {
  // As the paper's 15.1.doors: the utterance comes before any action.
  fs::path dir = dkg_copy();
  write(dir / "plans/observed/e1.1.keys.pddl", "; Can you get me the yellow key?\n");
  write(dir / "plans/completed/e1.1.keys.pddl",
        "(left human)\n(wait robot)\n(left human)\n(wait robot)\n" + read(dir / "plans/completed/e1.1.keys.pddl"));
  auto ds = Dataset::load(dir.string());
  EXPECT_TRUE(ds.plan("e1.1.keys").observed.actions.empty());
  EXPECT_EQ(ds.plan("e1.1.keys").observed.utterances.size(), 1u);
}

TEST_F(DatasetInput, EmptyUtteranceIsRejectedWithFileAndLine) {
  fs::path dir = dkg_copy();
  replace(dir / "plans/observed/e1.1.keys.pddl", "; Can you get me the yellow key?", ";  ");
  EXPECT_THAT(load_error(dir), HasSubstr("plans/observed/e1.1.keys.pddl:5:1: empty utterance"));
}

TEST_F(DatasetInput, WellFormedStimuliLoad) {
  fs::path dir = dkg_copy();
  EXPECT_FALSE(Dataset::load(dir.string()).stimulus("e1.1.keys"));  // stimuli.json is optional
  write(dir / "stimuli.json", "[" + stimulus("[1.0]") + ",\n" +
                                  stimulus("[2]", "6", "\"Can you unlock the yellow door for me?\"", "[[1, 2]]",
                                           "\"e2.1.doors\"", "\"doors\"") + "]");
  auto ds = Dataset::load(dir.string());
  auto st = ds.stimulus("e1.1.keys");
  ASSERT_TRUE(st);
  EXPECT_EQ(st->goal, 1);
  EXPECT_EQ(st->timesteps, 4);
  EXPECT_EQ(st->best_options, std::vector<int>{3});
  EXPECT_EQ(ds.stimulus("e2.1.doors")->best_options, (std::vector<int>{1, 2}));
}

TEST_F(DatasetInput, BadStimuliFieldsAreRejectedNamingEntryPlanAndField) {
  const std::string where = "stimuli.json: entry 2 (plan e1.1.keys): ";
  const std::string ok = stimulus("[2]", "6", "\"Can you unlock the yellow door for me?\"", "[[1]]", "\"e2.1.doors\"",
                                  "\"doors\"");
  struct Case {
    std::string entry, expected;
  };
  const std::vector<Case> cases = {
      {stimulus("[1.5]"), where + "field \"goal\": expected an integer, got 1.5"},
      {stimulus("[1e30]"), where + "field \"goal\": expected an integer from 0 to 2147483647, got 1e+30"},
      {stimulus("[-1]"), where + "field \"goal\": expected an integer from 0 to 2147483647, got -1"},
      {stimulus("\"gem2\""), where + "field \"goal\": expected an array of one element, got the string \"gem2\""},
      {stimulus("[]"), where + "field \"goal\": expected an array of one element, got an array of 0"},
      {stimulus("[1, 2]"), where + "field \"goal\": expected an array of one element, got an array of 2"},
      {stimulus("[null]"), where + "field \"goal\": expected an integer, got null"},
      {stimulus("[1]", "1e20"), where + "field \"timesteps\": expected an integer from 0 to 2147483647, got 1e+20"},
      {stimulus("[1]", "\"4\""), where + "field \"timesteps\": expected an integer, got the string \"4\""},
      {stimulus("[1]", "4", "3"), where + "field \"utterance\": expected a string, got 3"},
      {stimulus("[1]", "4", "\"Get the red key\""),
       where + "field \"utterance\": \"Get the red key\" differs from the observed plan's utterance"},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "\"x\""),
       where + "field \"best_option\": expected an array of one element, got the string \"x\""},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[3]"),
       where + "field \"best_option\": expected [[o, ...]], got [3]"},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[[0]]"),
       where + "field \"best_option\": expected an integer from 1 to 3, got 0"},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[[4]]"),
       where + "field \"best_option\": expected an integer from 1 to 3, got 4"},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[[3]]", "\"e1.1.keys\"", "\"doors\""),
       where + "field \"type\": \"doors\" differs from the plan's condition \"keys\""},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[[3]]", "\"e9.1.keys\""),
       "stimuli.json: entry 2 (plan e9.1.keys): no such plan in plans/observed/"},
      {stimulus("[1]", "4", "\"Can you get me the yellow key?\"", "[[3]]", "7"),
       "stimuli.json: entry 2: field \"name\": expected a string, got 7"},
      {"{\"type\": \"keys\"}", "stimuli.json: entry 2: field \"name\" is missing"},
      {"[1]", "stimuli.json: entry 2: expected an object, got an array"},
      {ok, "stimuli.json: entry 2 (plan e2.1.doors): a second entry for this plan (the first is entry 1)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.entry);
    fs::path dir = dkg_copy();
    write(dir / "stimuli.json", "[" + ok + ",\n" + c.entry + "]");
    std::string err = load_error(dir);
    EXPECT_THAT(err, HasSubstr(c.expected));
    EXPECT_THAT(err, Not(HasSubstr("json.exception")));
  }
  fs::path dir = dkg_copy();
  write(dir / "stimuli.json", "{}");
  EXPECT_THAT(load_error(dir), HasSubstr("stimuli.json: expected a JSON array of stimuli, got an object"));
}

TEST_F(DatasetInput, NonUtf8UtteranceIsRejectedWithFileAndLine) {
  fs::path dir = dkg_copy();
  replace(dir / "plans/observed/e1.1.keys.pddl", "yellow", "yell\xff\x64w");
  EXPECT_THAT(load_error(dir),
              HasSubstr("plans/observed/e1.1.keys.pddl:5:1: utterance is not valid UTF-8 (byte 0xff at offset 23 of the text)"));
  dir = dkg_copy();
  write(dir / "utterances/literal/e1.2.keys.txt", "Caf\xc3 red key\n");  // truncated sequence
  EXPECT_THAT(load_error(dir), HasSubstr("utterances/literal/e1.2.keys.txt:1:1: utterance is not valid UTF-8"));
  for (const char* bad : {"\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\x80"}) {  // overlong, surrogate, > U+10FFFF
    dir = dkg_copy();
    write(dir / "utterances/literal/e1.2.keys.txt", std::string("key ") + bad + "\n");
    EXPECT_THAT(load_error(dir), HasSubstr("not valid UTF-8")) << bad;
  }
}

TEST_F(DatasetInput, Utf8UtterancesLoad) {
  fs::path dir = dkg_copy();
  const std::string u = "Caf\xc3\xa9 \xe2\x98\x95, the r\xc3\xa9""d key \xf0\x9f\x94\x91 please";
  replace(dir / "plans/observed/e1.1.keys.pddl", "Can you get me the yellow key?", u);
  write(dir / "utterances/pragmatic/e1.1.keys.txt", u + "\n");
  auto ds = Dataset::load(dir.string());
  EXPECT_EQ(ds.plan("e1.1.keys").observed.utterances.at(0).text, u);
}

TEST_F(DatasetInput, OneBadPlanFileLeavesTheOtherPlansUsable) {
  fs::path dir = dkg_copy();
  write(dir / "plans/observed/e1.2.keys.pddl", "(up human)\n; Can you bring me\n(wait robot)\n; the red key?\n");
  auto ds = Dataset::load(dir.string());
  ASSERT_EQ(ds.plans().size(), 3u);
  ASSERT_EQ(ds.broken_plans().size(), 1u);
  EXPECT_EQ(ds.broken_plans()[0].id, "e1.2.keys");
  EXPECT_THAT(ds.broken_plans()[0].error, HasSubstr("plans/observed/e1.2.keys.pddl"));
  EXPECT_EQ(ds.plan("e1.1.keys").id, "e1.1.keys");
  EXPECT_EQ(ds.plan("e2.2.keys").id, "e2.2.keys");
  // The bad plan raises its own error when asked for, naming its file.
  try {
    ds.plan("e1.2.keys");
    FAIL() << "a plan that failed to load was returned";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("plan e1.2.keys could not be loaded"));
    EXPECT_THAT(std::string(e.what()), HasSubstr("plans/observed/e1.2.keys.pddl"));
  }
  // validate still lists it, with the others checked as usual.
  auto rep = validate_dataset(ds);
  ASSERT_EQ(rep.results.size(), 4u);
  EXPECT_EQ(rep.failed, 1);
  for (const auto& r : rep.results) {
    if (r.plan_id == "e1.2.keys") {
      EXPECT_FALSE(r.ok);
      EXPECT_THAT(r.error, HasSubstr("plans/observed/e1.2.keys.pddl"));
    } else {
      EXPECT_TRUE(r.ok) << r.plan_id << ": " << r.error;
    }
  }
}

TEST_F(DatasetInput, EveryBadPlanIsListedWithItsOwnFile) {
  fs::path dir = dkg_copy();
  fs::remove(dir / "plans/completed/e2.1.doors.pddl");
  write(dir / "utterances/literal/e1.1.keys.txt", "");
  auto ds = Dataset::load(dir.string());
  EXPECT_EQ(ds.plans().size(), 2u);
  ASSERT_EQ(ds.broken_plans().size(), 2u);
  EXPECT_EQ(ds.broken_plans()[0].id, "e1.1.keys");
  EXPECT_THAT(ds.broken_plans()[0].error, HasSubstr("utterances/literal/e1.1.keys.txt is empty"));
  EXPECT_EQ(ds.broken_plans()[1].id, "e2.1.doors");
  EXPECT_THAT(ds.broken_plans()[1].error, HasSubstr("missing completed plan for e2.1.doors"));
  EXPECT_EQ(validate_dataset(ds).failed, 2);
}

// A malformed stimuli.json concerns validation only: the plans load and run,
// and validate reports the file's error.
TEST_F(DatasetInput, BadStimuliFileDoesNotBlockThePlans) {
  fs::path dir = dkg_copy();
  write(dir / "stimuli.json", "[{\"name\": ");
  auto ds = Dataset::load(dir.string());
  EXPECT_EQ(ds.plans().size(), 4u);
  EXPECT_THAT(ds.stimuli_error(), HasSubstr("stimuli.json: malformed JSON"));
  EXPECT_NO_THROW(ds.task("e1"));
  auto rep = validate_dataset(ds);
  EXPECT_EQ(rep.failed, 4);
  for (const auto& r : rep.results) EXPECT_THAT(r.error, HasSubstr("stimuli.json")) << r.plan_id;
}

// `clips plan --problem` reads the problems only: a broken plan file or no
// plans at all do not concern it.
TEST_F(DatasetInput, ProblemsLoadWithoutReadingThePlans) {
  fs::path dir = dkg_copy();
  write(dir / "plans" / "observed" / "e1.9.bad.pddl", "(this is not a plan");
  auto ds = Dataset::load_problems(dir.string());
  EXPECT_TRUE(ds.plans().empty());
  EXPECT_TRUE(ds.broken_plans().empty());
  EXPECT_EQ(ds.problem_ids(), (std::vector<std::string>{"e1", "e2"}));
  EXPECT_GT(ds.task("e2")->num_actions(), 0u);
  // The full load still sees both.
  EXPECT_THAT(load_error(dir), HasSubstr("e1.9.bad"));
  fs::remove_all(dir / "plans");
  EXPECT_EQ(Dataset::load_problems(dir.string()).problem_ids().size(), 2u);
  EXPECT_THAT(load_error(dir), HasSubstr("has no plans/observed/"));
}

}  // namespace dataset_input_test

}  // namespace clips::data
