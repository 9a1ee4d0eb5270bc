#include "app/cli_conventions_test.hpp"

namespace clips::eval {
namespace cli_conventions_test {
TEST(CliExitCodes, HelpListsThem) {
  const auto r = run_stdout(clips() + "--help");
  EXPECT_EQ(r.status, 0);
  for (const char* line : {"Exit status:", "2  usage error", "3  input error", "4  no plan exists", "5  a time, node",
                           "6  the language model", "8  internal error"})
    EXPECT_TRUE(contains(r.out, line)) << line << "\n" << r.out;
}

TEST(CliExitCodes, Success0) {
  EXPECT_EQ(run(clips() + "show" + dkg() + " --plan e1.1.keys").status, 0);
}

TEST(CliExitCodes, SomeItemsFailed1) {
  ExamplesCopy copy;
  // The completion of e1.1.keys no longer picks up its gem: validate reports it and goes on.
  const fs::path completed = copy.dir / "plans/completed/e1.1.keys.pddl";
  std::string text = testing::read_text(completed);
  text = text.substr(0, text.rfind("(pickup human gem3)"));
  std::ofstream(completed) << text;
  const auto r = run(clips() + "validate --dataset " + copy.dir.string());
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "FAIL  e1.1.keys")) << r.out;
  EXPECT_TRUE(contains(r.out, "ok    e1.2.keys")) << r.out;
}

TEST(CliExitCodes, UsageErrors2) {
  for (const std::string& args : std::vector<std::string>{"", "frobnicate", "show --no-such-flag" + dkg(), "show" + dkg(),
                                 "plan" + dkg() + " --problem e1 --max-nodes 0",
                                 "infer" + dkg() + " --plan e1.1.keys --problem e1",
                                 "infer" + dkg() + " --problem e1",
                                 "infer" + dkg() + " --plan e1.1.keys --utterance hi"}) {
    const auto r = run(clips() + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
  }
}

TEST(CliExitCodes, InputErrors3) {
  for (const std::string& args : std::vector<std::string>{"show --dataset /nonexistent-clips-dir --plan 1.1.keys", "show" + dkg() + " --plan 9.9.x",
                                 "plan" + dkg() + " --problem e1 --goal '(has human'"}) {
    const auto r = run(clips() + args);
    EXPECT_EQ(r.status, 3) << args << "\n" << r.out;
  }
}

TEST(CliExitCodes, NoPlanExists4) {
  // c is heavy and may only stand on the table: A* exhausts the space.
  const std::string blocks = clips::paths::examples_dir() + "/blocks/";
  const auto r = run(clips() + "plan --domain " + blocks + "domain.pddl --problem " + blocks +
                     "p1.pddl --goal '(on c a)' --json");
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_TRUE(contains(r.out, "\"status\":\"failure\"")) << r.out;
}

TEST(CliExitCodes, LimitReached5) {
  const auto r = run(clips() + "plan" + dkg() + " --problem e1 --goal '(has human gem1)' --max-nodes 1 --json");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_TRUE(contains(r.out, "\"status\":\"max_nodes\"")) << r.out;
}

TEST(CliExitCodes, LanguageModelFailure6) {
  // No server listens on port 9 (discard) of the loopback: the connection is refused.
  const auto r = run("CLIPS_LM_CACHE_DIR=off " + clips() + "listen" + dkg() +
                     " --plan e1.1.keys --lm openai --lm-base-url http://127.0.0.1:9/v1 --lm-timeout 2");
  EXPECT_EQ(r.status, 6) << r.out;
}

TEST(CliStreams, WroteNotesGoToStderr) {
  testing::TempDir tmp("streams");
  const std::string png = (tmp.path / "f.png").string();
  auto r = run_stdout(clips() + "render" + dkg() + " --plan e1.1.keys --out " + png);
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(fs::exists(png));
  r = run_stdout(clips() + "bench" + dkg() + " --plans e1.1.keys --methods clips --no-progress --out " +
                 (tmp.path / "b").string());
  EXPECT_EQ(r.status, 0);
  EXPECT_FALSE(contains(r.out, "wrote")) << r.out;
  EXPECT_TRUE(contains(r.out, "clips")) << r.out;  // the table itself
}

TEST(BenchFilesTest, PosteriorsResultsAndProvenance) {
  BenchFiles b(examples_dkg(), "--plans e1.1.keys,e2.1.doors --methods clips,action_only,literal_naive");
  ASSERT_EQ(b.result.status, 0) << b.result.out;

  // summary.json: provenance.
  const auto j = nlohmann::json::parse(b.summary);
  EXPECT_TRUE(std::regex_match(j["clips_version"].get<std::string>(), std::regex(R"(\d+\.\d+\.\d+)")));
  EXPECT_TRUE(j.contains("git_commit"));
  EXPECT_TRUE(std::regex_match(j["date"].get<std::string>(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_EQ(j["seed"].get<uint64_t>(), 4294967296ull);
  EXPECT_EQ(j["assistance"], "default");
  EXPECT_EQ(j["methods_requested"], nlohmann::json({"clips", "action_only", "literal_naive"}));
  EXPECT_EQ(j["methods"]["clips"]["n"], 2);
  EXPECT_EQ(j["methods"]["literal_naive"]["n"], 2);
  EXPECT_FALSE(j["lm"].get<std::string>().empty());
  EXPECT_EQ(j["dataset_fingerprint"].get<std::string>().size(), 16u);

  // results.csv: a domain column and seconds that are not rounded to zero.
  std::istringstream rin(b.results);
  std::string line;
  std::getline(rin, line);
  const auto header = split(line);
  ASSERT_EQ(header.front(), "plan");
  ASSERT_NE(std::find(header.begin(), header.end(), "domain"), header.end());
  ASSERT_EQ(header.back(), "request_done");
  const size_t seconds_col = std::find(header.begin(), header.end(), "seconds") - header.begin();
  const size_t domain_col = std::find(header.begin(), header.end(), "domain") - header.begin();
  int rows = 0;
  while (std::getline(rin, line)) {
    if (line.empty()) continue;
    ++rows;
    const auto f = split(line);  // no quoted commas in these rows' first fields
    EXPECT_EQ(f.at(f.size() - (header.size() - domain_col)), "doors-keys-gems") << line;
    EXPECT_GT(std::stod(f.at(seconds_col)), 0.0) << line;
  }
  EXPECT_EQ(rows, 6);

  // posteriors.csv: long format, per inference method and step; sums to 1.
  std::istringstream pin(b.posteriors);
  std::getline(pin, line);
  EXPECT_EQ(line, "domain,plan,method,t,goal,probability");
  std::map<std::string, double> sums;  // plan/method/t -> sum over goals
  std::set<std::string> methods;
  bool full_precision = false;
  while (std::getline(pin, line)) {
    const auto f = split(line);
    ASSERT_EQ(f.size(), 6u) << line;
    EXPECT_EQ(f[0], "doors-keys-gems");
    methods.insert(f[2]);
    sums[f[1] + "/" + f[2] + "/" + f[3]] += std::stod(f[5]);
    full_precision |= f[5].size() > 12;
  }
  EXPECT_EQ(methods, (std::set<std::string>{"clips", "action_only"}));  // literal listeners have no posterior
  EXPECT_TRUE(full_precision);
  EXPECT_TRUE(sums.count("e1.1.keys/clips/0"));
  EXPECT_TRUE(sums.count("e1.1.keys/clips/4"));   // T = 4 observed actions
  EXPECT_FALSE(sums.count("e1.1.keys/clips/5"));
  for (const auto& [k, v] : sums) EXPECT_NEAR(v, 1.0, 1e-9) << k;

  // The final step's CLIPS posterior is the goal_posterior of results.csv (to its 4 digits).
  auto jr = run_stdout(clips() + "infer" + dkg() + " --plan e1.1.keys --json");
  ASSERT_EQ(jr.status, 0);
  const auto inf = nlohmann::json::parse(jr.out);
  const auto last = testing::goal_probabilities(inf["steps"].back()["posterior"]);
  for (size_t g = 0; g < last.size(); ++g) {
    const std::string key = "doors-keys-gems,e1.1.keys,clips,4," + inf["goals"][g].get<std::string>() + ",";
    const size_t at = b.posteriors.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    const double p = std::stod(b.posteriors.substr(at + key.size()));
    EXPECT_NEAR(p, last[g], 1e-12) << key;
  }
}

TEST(CliObservations, InlineActionsReproduceTheDatasetPlan) {
  const auto ref = run_stdout(clips() + "infer" + dkg() + " --plan e1.1.keys --json");
  ASSERT_EQ(ref.status, 0);
  const auto adhoc = run_stdout(clips() + "infer" + dkg() + " --problem e1 --actions " + sq(kE11Actions) +
                                " --utterance " + sq(kE11Utterance) + " --utterance-step 4 --json");
  ASSERT_EQ(adhoc.status, 0) << adhoc.out;
  const auto a = nlohmann::json::parse(ref.out), b = nlohmann::json::parse(adhoc.out);
  EXPECT_EQ(a["goals"], b["goals"]);
  EXPECT_TRUE(b["true_goal"].is_null());
  ASSERT_EQ(a["steps"].size(), b["steps"].size());
  for (size_t t = 0; t < a["steps"].size(); ++t) {
    const auto pa = testing::goal_probabilities(a["steps"][t]["posterior"]),
               pb = testing::goal_probabilities(b["steps"][t]["posterior"]);
    ASSERT_EQ(pa.size(), a["goals"].size());
    ASSERT_EQ(pb.size(), pa.size());
    for (size_t g = 0; g < pa.size(); ++g) EXPECT_NEAR(pa[g], pb[g], 1e-12) << "t=" << t << " g=" << g;
  }
}

TEST(CliObservations, ActionsFromAPlanFile) {
  const auto ref = run_stdout(clips() + "infer" + dkg() + " --plan e1.1.keys --json");
  const auto adhoc = run_stdout(clips() + "infer" + dkg() + " --problem e1 --actions " + examples_dkg() +
                                "/plans/observed/e1.1.keys.pddl --json");
  ASSERT_EQ(adhoc.status, 0) << adhoc.out;
  EXPECT_EQ(untimed_steps(ref.out), untimed_steps(adhoc.out));
}

TEST(CliObservations, TheUtteranceStepMatters) {
  const auto before = run_stdout(clips() + "infer" + dkg() + " --problem e1 --actions " + sq(kE11Actions) +
                                 " --utterance " + sq(kE11Utterance) + " --json");
  ASSERT_EQ(before.status, 0) << before.out;
  const auto j = nlohmann::json::parse(before.out);
  // Said before the first action: the posterior at t = 0 already moved away from uniform.
  const auto p0 = testing::goal_probabilities(j["steps"][0]["posterior"]);
  ASSERT_FALSE(p0.empty());
  EXPECT_GT(std::abs(p0[0] - 1.0 / p0.size()), 1e-3) << j["steps"][0]["posterior"];
}

TEST(CliObservations, ErrorsNameTheAction) {
  struct Case {
    std::string actions, expect1, expect2;
  };
  for (const auto& c : std::vector<Case>{{"(left human) (pickup human key9)", "key9", "action 2 of 2"},
                                         {"(left human) (left human)", "not applicable", "action 2 of 2"},
                                         {"(fly human)", "unknown action", "action 1 of 1"},
                                         {"(left human", "--actions", ""}}) {
    const auto r = run(clips() + "infer" + dkg() + " --problem e1 --actions " + sq(c.actions) + " --json");
    EXPECT_EQ(r.status, 3) << c.actions << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, c.expect1)) << r.out;
    EXPECT_TRUE(contains(r.out, c.expect2)) << r.out;
  }
  auto r = run(clips() + "infer" + dkg() + " --problem e9 --actions '(left human)'");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "problems/e9.pddl")) << r.out;
  r = run(clips() + "infer" + dkg() + " --problem e1 --actions '(left human)' --utterance hi --utterance-step 2");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "--utterance-step 2")) << r.out;
  r = run(clips() + "infer" + dkg() + " --problem e1 --actions /nonexistent/plan.pddl");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "no such file")) << r.out;
}

TEST(CliObservations, AssistNamesTheAssistantsNextAction) {
  // After three actions it is the robot's turn.
  const auto r = run_stdout(clips() + "assist" + dkg() + " --problem e1 --actions " +
                            sq("(left human) (wait robot) (left human)") + " --utterance " + sq(kE11Utterance) +
                            " --utterance-step 3 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["next_actor"], "robot");
  ASSERT_TRUE(j["action"].is_string()) << j;
  EXPECT_TRUE(contains(j["action"].get<std::string>(), "robot")) << j;
  double sum = 0;
  for (const auto& p : j["goal_posterior"]) sum += p.get<double>();
  EXPECT_NEAR(sum, 1.0, 1e-9);
  // After four it is the human's: nothing to decide.
  const auto h = run_stdout(clips() + "assist" + dkg() + " --problem e1 --actions " + sq(kE11Actions) + " --json");
  ASSERT_EQ(h.status, 0) << h.out;
  EXPECT_TRUE(nlohmann::json::parse(h.out)["action"].is_null());
}

TEST(CliSmaller, SeedRange) {
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "x"}) {
    const auto r = run(clips() + "bench" + dkg() + " --plans e1.1.keys --methods clips --seed " + seed);
    EXPECT_EQ(r.status, 2) << seed << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "--seed")) << r.out;
  }
  EXPECT_EQ(run(clips() + "assist" + dkg() + " --plan e1.1.keys --seed 18446744073709551615").status, 0);
}

TEST(CliSmaller, EmptyOutIsAnError) {
  const auto r = run(clips() + "bench" + dkg() + " --plans e1.1.keys --methods clips --out ''");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--out is empty")) << r.out;
  EXPECT_FALSE(contains(r.out, "P(g_true)")) << "ran before failing\n" << r.out;
}

TEST(CliSmaller, RenderRefusesToOverwriteAndChecksTheExtension) {
  testing::TempDir tmp("render-out");
  const std::string png = (tmp.path / "f.png").string();
  std::ofstream(png) << "keep me";
  auto r = run(clips() + "render" + dkg() + " --plan e1.1.keys --out " + png);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "--force")) << r.out;
  EXPECT_EQ(testing::read_text(png), "keep me");
  r = run(clips() + "render" + dkg() + " --plan e1.1.keys --force --out " + png);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(testing::read_text(png), "keep me");
  r = run(clips() + "render" + dkg() + " --plan e1.1.keys --out " + (tmp.path / "f.gif").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, ".png")) << r.out;
  EXPECT_FALSE(fs::exists(tmp.path / "f.gif"));
  r = run(clips() + "render" + dkg() + " --plan e1.1.keys --gif " + (tmp.path / "g.png").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_FALSE(fs::exists(tmp.path / "g.png"));
}

TEST(CliSmaller, APlanPathThatIsADirectoryIsCalledOne) {
  ExamplesCopy copy;
  fs::create_directory(copy.dir / "plans/observed/e3.1.keys.pddl");
  // The directory is set aside as a broken plan: asking for it names it.
  auto r = run(clips() + "show --dataset " + copy.dir.string() + " --plan e3.1.keys");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "is a directory")) << r.out;
  EXPECT_FALSE(contains(r.out, "empty")) << r.out;
  r = run(clips() + "infer" + dkg() + " --problem e1 --actions " + copy.dir.string() + "/plans");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "is a directory")) << r.out;
}

TEST(CliSmaller, ClipsDatasetIsTheDefaultDataset) {
  auto r = run("CLIPS_DATASET=" + examples_dkg() + " " + clips() + "show --plan e1.1.keys");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "plan e1.1.keys")) << r.out;
  // A folder of datasets: --dataset names one of them.
  r = run("CLIPS_DATASET=" + clips::paths::examples_dir() + " " + clips() + "show --dataset doors-keys-gems --plan e1.1.keys");
  EXPECT_EQ(r.status, 0) << r.out;
  r = run("CLIPS_DATASET=" + clips::paths::examples_dir() + " " + clips() + "show --plan e1.1.keys");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--dataset doors-keys-gems")) << r.out;
  r = run("env -u CLIPS_DATASET " + clips() + "show --plan e1.1.keys");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "CLIPS_DATASET")) << r.out;
}

TEST(CliSmaller, CommandLineUtterancesMustBeUtf8BeforeAnyWork) {
  // printf writes the bytes 0xff and 0xc3 (a lead byte with no continuation).
  for (const std::string& cmd : std::vector<std::string>{"listen" + dkg() + " --plan e1.1.keys --json --utterance \"$(printf 'red \\377 key')\"",
                                "infer" + dkg() + " --problem e1 --json --utterance \"$(printf 'red \\303 key')\""}) {
    const auto r = run(clips() + cmd);
    EXPECT_EQ(r.status, 3) << cmd << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "not valid UTF-8")) << r.out;
    EXPECT_FALSE(contains(r.out, "internal")) << r.out;
  }
}

}  // namespace cli_conventions_test

}  // namespace clips::eval
