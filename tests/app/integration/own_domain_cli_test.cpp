// A user's own domain through the CLI (issue 42): tests/fixtures/garden has no
// turn idiom, no `frozen` and no no-op; its pack names the no-op `idle` and the
// turn predicate `turn`. `clips validate` rehearses bench on it, `clips assist`
// assists on it, and what bench would stop at is reported by validate, naming
// the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>

#include <nlohmann/json.hpp>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

namespace fs = std::filesystem;
using testing::clips_binary;
using testing::contains;
using testing::run;

std::string garden() { return clips::paths::source_dir() + "/tests/fixtures/garden"; }
std::string sq(const std::string& s) { return "'" + s + "'"; }

// A scratch copy of the garden with its pack.json rewritten by `edit`.
struct GardenCopy {
  testing::TempDir dir{"garden"};
  std::string ds = (dir.path / "garden").string();
  explicit GardenCopy(const std::function<std::string(std::string)>& edit) {
    fs::copy(garden(), ds, fs::copy_options::recursive);
    const fs::path pack = fs::path(ds) / "pack.json";
    const std::string text = edit(testing::read_text(pack));
    std::ofstream(pack) << text;
  }
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(CliOwnDomain, ValidateRehearsesBenchOnThePacksNoOpAndTurnPredicate) {
  const auto r = run(clips_binary() + " validate --dataset " + garden());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "pack.json conforms to")) << r.out;
  EXPECT_TRUE(contains(r.out, "validated 2 plans, 0 failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "bench set-up on plan 1.1.basil: 4 methods ok, 0 failed, 0 warnings")) << r.out;
  for (const char* m : {"clips", "lang_only", "action_only", "literal"})
    EXPECT_TRUE(std::regex_search(r.out, std::regex(std::string("ok    bench set-up: ") + m + " +on plan 1.1.basil"))) << m;
}

// The repo's garden pack leaves what put and unlock mean, and where put leaves
// its item, to clips: validate says what it found.
TEST(CliOwnDomain, ValidateReportsWhatItDerivedFromTheEffects) {
  const std::string ds = clips::paths::source_dir() + "/data/datasets/garden";
  const auto r = run(clips_binary() + " validate --plans-only --dataset " + ds);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "derived from the effects: unlock means (not (locked $3))")) << r.out;
  EXPECT_TRUE(contains(r.out, "derived from the effects: put leaves its argument 2 at its argument 3")) << r.out;
  // unlock is about a place (the greenhouse, the shed): commands name it.
  EXPECT_TRUE(contains(r.out, "derived from the types: unlock's argument 3 is a place, named in commands")) << r.out;
  EXPECT_FALSE(contains(r.out, "derived from the types: pickup's argument")) << r.out;
  // pickup's meaning is the pack's own goal_atoms entry, and pickup leaves nothing anywhere.
  EXPECT_FALSE(contains(r.out, "derived from the effects: pickup")) << r.out;
  // The garden declares its spade and rake tools: WordNet's shovel and rake,
  // not its playing card and libertine; its tool keeps the first sense.
  EXPECT_TRUE(std::regex_search(r.out, std::regex("derived from the types: spade means \"[^\"]*shovel"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("derived from the types: rake means \"[^\"]*tool"))) << r.out;
  EXPECT_FALSE(contains(r.out, "derived from the types: tool")) << r.out;
}

// Where both the shed and the greenhouse are locked, "unlock the greenhouse"
// asks for that one: the listener's commands name the place unlocked, and
// of the commands that unlock one of the two, nearly all the mass is on the
// place said. (With the place lifted, both read "(unlock you ?place1)".)
TEST(CliOwnDomain, TheListenerKnowsWhichPlaceToUnlock) {
  const std::string ds = clips::paths::source_dir() + "/data/datasets/garden";
  const auto mass = [&](const std::string& utterance) {
    const auto r = run("CLIPS_LM_CACHE_DIR=off " + clips_binary() + " listen --dataset " + ds +
                       " --plan 4.4.plant-roses --json --utterance " + sq(utterance));
    EXPECT_EQ(r.status, 0) << r.out;
    std::map<std::string, double> out;
    if (r.status != 0 || r.out.find('{') == std::string::npos) return out;
    const auto j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
    for (const auto& c : j.at("commands")) {
      std::vector<std::string> unlocked;
      for (const char* place : {"shed", "greenhouse"})
        if (std::regex_search(c.at("command").get<std::string>(),
                              std::regex(std::string(R"(\(unlock you \?key\d+ )") + place + "[ )]")))
          unlocked.push_back(place);
      if (unlocked.size() == 1) out[unlocked[0]] += c.at("prob").get<double>();
    }
    return out;
  };
  // (0.50 before issue 60's model changes, 0.496 after: the rest is spread
  // over commands that unlock nothing.)
  auto m = mass("Could you unlock the greenhouse?");
  EXPECT_GT(m["greenhouse"], 0.45);
  EXPECT_GT(m["greenhouse"], 20 * m["shed"]);
  m = mass("Can you open up the shed for me?");
  EXPECT_GT(m["shed"], 0.5);
  EXPECT_GT(m["shed"], 20 * m["greenhouse"]);
}

// Type names are read through WordNet; validate says how, and warns of a
// name WordNet does not know at all.
TEST(CliOwnDomain, ValidateSaysWhichWordEachTypeIsReadAs) {
  // The fixture's `seed` type, renamed throughout (domain, problem, pack).
  const auto renamed = [](const std::string& name) {
    auto c = std::make_unique<GardenCopy>([](std::string t) { return t; });
    for (const char* f : {"domain.pddl", "problems/1.pddl", "pack.json"}) {
      const fs::path file = fs::path(c->ds) / f;
      const std::string text = std::regex_replace(testing::read_text(file), std::regex("\\bseed\\b"), name);
      std::ofstream(file) << text;
    }
    return c;
  };
  {
    const auto c = renamed("seeds");  // WordNet has "seed", not "seeds"
    const auto r = run(clips_binary() + " validate --plans-only --dataset " + c->ds);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "ok    derived from the types: seeds is read as WordNet's \"seed\"")) << r.out;
    EXPECT_FALSE(contains(r.out, "does not know")) << r.out;
  }
  {
    const auto c = renamed("zorblat");
    const auto r = run(clips_binary() + " validate --plans-only --dataset " + c->ds);
    EXPECT_EQ(r.status, 0) << r.out;  // a warning: the domain still works
    EXPECT_TRUE(contains(r.out, "WARN  WordNet does not know the type name 'zorblat'")) << r.out;
  }
  // A name WordNet has as it is gets no line.
  const auto r = run(clips_binary() + " validate --plans-only --dataset " + garden());
  EXPECT_FALSE(contains(r.out, "is read as")) << r.out;
}

TEST(CliOwnDomain, AssistTakesTurnsWithIdle) {
  auto r = run(clips_binary() + " assist --dataset " + garden() + " --plan 1.1.basil --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["goal_reached"].get<bool>()) << j;
  const auto plan = j["plan"].get<std::vector<std::string>>();
  ASSERT_GE(plan.size(), 2u);
  EXPECT_EQ(plan[0], "(take bot basil1 shed)") << j;
  // Turns alternate: the bot's actions at even positions, the gardener's at odd ones.
  for (size_t i = 0; i < plan.size(); ++i)
    EXPECT_TRUE(contains(plan[i], i % 2 == 0 ? " bot" : " gardener")) << i << ": " << plan[i];
  EXPECT_EQ(j["true_options"], nlohmann::json::array({"basil1"}));
  // The next action after ad-hoc observations: the bot's turn after the gardener idles.
  r = run(clips_binary() + " assist --dataset " + garden() + " --problem 1 --actions " + sq("(idle gardener)") +
          " --utterance " + sq("Could you bring me the green seeds?") + " --utterance-step 1 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto next = nlohmann::json::parse(r.out);
  EXPECT_EQ(next["next_actor"], "bot");
  EXPECT_EQ(next["action"], "(take bot basil1 shed)");
}

TEST(CliOwnDomain, ValidateNamesWhatBenchWouldStopAt) {
  // A goal atom naming a missing argument: refused when the pack loads
  // (issue 46; it used to pass and fail in `listen`).
  {
    GardenCopy c([](std::string t) { return replaced(t, "(holding $1 $2)", "(holding $1 $7)"); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "language.goal_atoms.take[0]: '$7' in \"(holding $1 $7)\" names parameter 7")) << r.out;
  }
  // A goal atom naming a predicate the domain lacks: the literal listener's
  // goal, which the bench rehearsal sets up and reports.
  {
    GardenCopy c([](std::string t) { return replaced(t, "(holding $1 $2)", "(holdin $1 $2)"); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "validated 2 plans, 0 failed")) << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL  bench set-up: literal")) << r.out;
    EXPECT_TRUE(contains(r.out, "unknown predicate 'holdin'")) << r.out;
  }
  // No goal atoms for a salient action: they come from its effects, and every
  // method, the literal listener included, is set up.
  {
    GardenCopy c([](std::string t) { return replaced(t, ",\n    \"goal_atoms\": {\"take\": [\"(holding $1 $2)\"]}", ""); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_FALSE(contains(r.out, "WARN  bench set-up: ")) << r.out;
    EXPECT_TRUE(contains(r.out, "ok    bench set-up: literal")) << r.out;
    EXPECT_TRUE(contains(r.out, "4 methods ok, 0 failed, 0 warnings")) << r.out;
  }
  // A misspelt field: the schema and the reader name it (an input error).
  {
    GardenCopy c([](std::string t) { return replaced(t, "\"horizon\"", "\"horizn\""); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "pack.json: roles.horizn: unknown field")) << r.out;
  }
  // A missing few-shot file.
  {
    GardenCopy c([](std::string t) { return replaced(t, "\"fewshot.tsv\"", "\"examples.tsv\""); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "fewshot.file: no file")) << r.out;
  }
  // Roles naming an object the problems lack.
  {
    GardenCopy c([](std::string t) { return replaced(t, "\"assistant\": \"bot\"", "\"assistant\": \"robot\""); });
    const auto r = run(clips_binary() + " validate --dataset " + c.ds);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "roles.assistant names 'robot', which is not an object of this problem")) << r.out;
  }
}


// A method that fails on every plan fails only its own rows: the others'
// rows stay in results.csv and summary.json counts what ran; the exit status
// says that something failed (1).
TEST(CliOwnDomain, OneFailingMethodLeavesTheOthersRows) {
  GardenCopy c([](std::string t) { return replaced(t, "(holding $1 $2)", "(holdin $1 $2)"); });
  const std::string out = (fs::path(c.ds).parent_path() / "out").string();
  const auto r = run(clips_binary() + " bench --no-progress -j 1 --methods clips,literal --dataset " + c.ds +
                     " --out " + out);
  EXPECT_TRUE(std::regex_search(r.out, std::regex("literal failed on 1\\.1\\.basil: <goal>:1:[0-9]+: unknown predicate 'holdin'")))
      << r.out;
  const std::string csv = testing::read_text(fs::path(out) / "results.csv");
  for (const char* plan : {"1.1.basil", "1.2.tomato"}) {
    EXPECT_TRUE(std::regex_search(csv, std::regex(std::string("\n") + plan + ",clips,0\\.[0-9]+,[^\n]*,,garden,,\n")))
        << plan << "\n" << csv;
    EXPECT_TRUE(std::regex_search(csv, std::regex(std::string("\n") + plan + ",literal,[^\n]*unknown predicate")))
        << plan << "\n" << csv;
  }
  const auto summary = nlohmann::json::parse(testing::read_text(fs::path(out) / "summary.json"));
  EXPECT_EQ(summary["methods"]["clips"]["n"], 2);
  EXPECT_EQ(summary["methods"]["literal"]["n"], 0);
  EXPECT_EQ(summary["failed_methods"], 2);
  EXPECT_EQ(summary["failed_plans"], 0);
  EXPECT_EQ(r.status, 1) << r.out;
}


// `clips assist --explain` lists the decisions where actions tied in value,
// with each one's request score and the action taken.
TEST(CliOwnDomain, AssistExplainShowsTheTies) {
  const std::string ws = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop";
  auto r = run(clips_binary() + " assist --dataset " + ws + " --plan 3.3.birdhouse --explain");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "request rule (")) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("step [0-9]+: tied \\(.*request -?[0-9.]+\\).*; took \\("))) << r.out;
  r = run(clips_binary() + " assist --json --dataset " + ws + " --plan 3.3.birdhouse --explain");
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("ties"));
  EXPECT_FALSE(j["ties"].empty());
}

// `clips infer --explain` lists each hypothesis' commands once: an alone
// twin says whose words it speaks instead of repeating its base's list.
TEST(CliOwnDomain, InferExplainFoldsTheAloneTwins) {
  const std::string ws = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop";
  auto r = run(clips_binary() + " infer --dataset " + ws + " --plan 3.3.birdhouse --explain --top 1");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("birdhouse/default-alone +-?[0-9.]+  \\(speaks as birdhouse/default\\)")))
      << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("birdhouse/default +-?[0-9.]+  \\([0-9]+ commands?\\)"))) << r.out;
}

// instructions.tsv's `requested` column: the bench says, per plan and
// method, whether the assistant did what it was explicitly asked. "Could you
// bring me the green seeds?" asks for (holding gardener basil1).
TEST(CliOwnDomain, BenchSaysWhetherTheRequestWasDone) {
  GardenCopy c([](std::string pack) { return pack; });
  std::ofstream(fs::path(c.ds) / "instructions.tsv")
      << "plan\tsplit\tcategories\trequested\n1.1.basil\ttest\tdirect\t(holding gardener basil1)\n"
         "1.2.tomato\tdev\tgoal\t\n";
  const std::string out = (c.dir.path / "out").string();
  auto r = run(clips_binary() + " bench --no-progress -j 1 --methods clips,action_only --dataset " + c.ds + " --out " + out);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "Explicit requests done")) << r.out;
  const std::string csv = testing::read_text(fs::path(out) / "results.csv");
  EXPECT_TRUE(contains(csv.substr(0, csv.find('\n')), ",domain,requested,request_done")) << csv;
  // CLIPS hears the request and hands the seeds over.
  EXPECT_TRUE(std::regex_search(csv, std::regex("\n1\\.1\\.basil,clips,[^\n]*,garden,\"\\(holding gardener basil1\\)\",1\n")))
      << csv;
  // A plan that asked nothing has both columns empty.
  EXPECT_TRUE(std::regex_search(csv, std::regex("\n1\\.2\\.tomato,clips,[^\n]*,garden,,\n"))) << csv;
  const auto summary = nlohmann::json::parse(testing::read_text(fs::path(out) / "summary.json"));
  const auto& req = summary["methods"]["clips"]["requests"];
  EXPECT_EQ(req["all"]["asked"], 1);
  EXPECT_EQ(req["all"]["done"], 1);
  EXPECT_EQ(req["test"]["asked"], 1);

  // An atom the problem does not have fails the plan, naming the file and plan.
  std::ofstream(fs::path(c.ds) / "instructions.tsv")
      << "plan\tsplit\tcategories\trequested\n1.1.basil\ttest\tdirect\t(holding gardener rose9)\n";
  r = run(clips_binary() + " bench --no-progress -j 1 --methods clips --dataset " + c.ds + " --out " + out);
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "instructions.tsv, plan 1.1.basil")) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown object 'rose9'")) << r.out;
}

}  // namespace
}  // namespace clips::eval
