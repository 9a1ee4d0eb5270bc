// Bad input on the command line: a hostile user's probes, one
// test each. Every one must end with a clear message and an exit status
// below 8 (no internal error, no signal) within its limit; every command
// runs under `timeout`, so a hang is a failure, not a stuck suite.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "eval/support.hpp"
#include "lm/embedded_model.hpp"
#include "lm/fake_openai_server.hpp"
#include "util/error.hpp"

namespace clips::eval {
namespace {

namespace fs = std::filesystem;
using lm::fake::FakeOpenAiServer;
using nlohmann::json;
using testing::contains;
using testing::run;

std::string clips(int seconds = 120) { return "timeout " + std::to_string(seconds) + " " + testing::clips_binary(); }
std::string ex() { return testing::examples_dkg(); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A scratch copy of the repo's workshop dataset, whose pack.json and goal
// definitions the tests break.
struct WorkshopCopy {
  testing::TempDir dir;
  std::string ds = (dir.path / "workshop").string();
  explicit WorkshopCopy(const std::string& tag) : dir(tag) {
    fs::copy(clips::paths::source_dir() + "/data/datasets/workshop", ds, fs::copy_options::recursive);
  }
  json pack() const { return json::parse(testing::read_text(fs::path(ds) / "pack.json")); }
  void write_pack(const json& p) const { std::ofstream(fs::path(ds) / "pack.json") << p.dump(2); }
  void write(const std::string& relative, const std::string& text) const {
    std::ofstream(fs::path(ds) / relative) << text;
  }
  std::string infer() const { return clips() + " infer --dataset " + ds + " --plan 1.1.table"; }
};

TEST(CliRefusesBadInput, NanAndInfinityAreRefusedByEveryNumberFlag) {
  const std::string infer = clips() + " infer --dataset " + ex() + " --plan e1.1.keys";
  const std::string plan = clips() + " plan --dataset " + ex() + " --problem e1 --goal '(has human gem1)'";
  const std::string listen = clips() + " listen --dataset " + ex() + " --plan e1.1.keys";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {infer + " --utterance-exponent nan", "--utterance-exponent"},
      {infer + " --utterance-noise nan", "--utterance-noise"},
      {infer + " --utterance-noise -nan", "--utterance-noise"},
      {infer + " --time-limit inf", "--time-limit"},
      {listen + " --lm-max-reply-mb nan", "--lm-max-reply-mb"},
      {listen + " --lm-timeout NaN", "--lm-timeout"},
      {plan + " --weight nan", "--weight"},
      {plan + " --max-memory nan", "--max-memory"},
      {plan + " --max-memory infinity", "--max-memory"},
  };
  for (const auto& [cmd, flag] : cases) {
    const auto r = run(cmd);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, flag)) << cmd << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "-8796093022208")) << r.out;  // the NaN memory limit of before
  }
  // The check is on every floating-point option, not a list: any NaN is a
  // usage error naming it ("not a finite number" or a range check's words).
  EXPECT_TRUE(contains(run(infer + " --utterance-exponent nan").out, "not a finite number"));
}

TEST(CliRefusesBadInput, GenerateRefusesCountsItCannotFinish) {
  testing::TempDir tmp("issue61-generate");
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run(clips(30) + " generate --problems 1000000000 --out " + tmp.str() + "/g");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--problems")) << r.out;
  EXPECT_LT(seconds_since(t0), 10);
  for (const char* flag : {"--plans 1000000", "--max-steps 100000000", "--max-nodes 99999999999999"}) {
    const std::string bad = flag;
    const auto b = run(clips(30) + " generate " + bad + " --out " + tmp.str() + "/g");
    EXPECT_EQ(b.status, 2) << bad << "\n" << b.out;
    EXPECT_TRUE(contains(b.out, bad.substr(0, bad.find(' ')))) << b.out;
  }
}

TEST(CliRefusesBadInput, BaseUrlWithAnEmptyPortIsRefused) {
  const std::string listen = clips() + " listen --dataset " + ex() + " --plan e1.1.keys";
  // libcurl reads "http://127.0.0.1:/v1" as port 80.
  auto r = run(listen + " --lm openai --lm-base-url http://127.0.0.1:/v1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--lm-base-url")) << r.out;
  EXPECT_TRUE(contains(r.out, "port")) << r.out;
  for (const char* url : {"http://127.0.0.1:99999/v1", "http://127.0.0.1:8x/v1", "http://:8000/v1", "http://"}) {
    const std::string bad = url;
    r = run(listen + " --lm openai --lm-base-url '" + bad + "'");
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.out;
  }
  // From the environment: refused before any request, naming the variable.
  r = run("CLIPS_LM_CACHE_DIR=off CLIPS_LM_BASE_URL=http://127.0.0.1:/v1 OPENAI_API_KEY=test " + listen + " --lm openai");
  EXPECT_EQ(r.status, 6) << r.out;
  EXPECT_TRUE(contains(r.out, "CLIPS_LM_BASE_URL")) << r.out;
}

// The score request of `clips lm-score` against a fake server, with a prompt file.
struct LmScore {
  testing::TempDir tmp{"issue61-lm"};
  std::string command(const FakeOpenAiServer& server, const std::string& timeout) {
    std::ofstream(tmp.path / "prompt.txt") << "Input: (pickup robot key1)\nOutput:";
    return "CLIPS_LM_CACHE_DIR=off OPENAI_API_KEY=test " + clips() + " lm-score --lm openai --lm-model fake" +
           " --lm-base-url " + server.base_url() + " --lm-timeout " + timeout + " --prompt-file " +
           (tmp.path / "prompt.txt").string() + " --continuation 'Get the key.'";
  }
};

TEST(CliRefusesBadInput, RetryAfterIsCappedByTheTimeout) {
  for (const std::string& wait : {std::string("100000"), std::string("Thu, 01 Jan 2099 00:00:00 GMT")}) {
    FakeOpenAiServer server;
    lm::fake::FakeFaults f;
    f.fail_first = 1000;
    f.fail_status = wait == "100000" ? 429 : 503;
    f.retry_after = wait;
    server.set_faults(f);
    server.start();
    LmScore lm;
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = run(lm.command(server, "3"));
    const double took = seconds_since(t0);
    server.stop();
    EXPECT_EQ(r.status, 6) << wait << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "Retry-After")) << r.out;
    EXPECT_TRUE(contains(r.out, "--lm-timeout")) << r.out;
    // The waits add up to the 3 s timeout at most: well within 10 s of it.
    EXPECT_LT(took, 13) << wait << "\n" << r.out;
  }
}

TEST(CliRefusesBadInput, ALogProbBeyondADoubleIsNamed) {
  FakeOpenAiServer server;
  lm::fake::FakeFaults f;
  f.reply = lm::fake::FakeReply::HugeNumber;
  server.set_faults(f);
  server.start();
  LmScore lm;
  const auto r = run(lm.command(server, "10"));
  server.stop();
  EXPECT_EQ(r.status, 6) << r.out;
  EXPECT_TRUE(contains(r.out, "out of range for a double")) << r.out;
  EXPECT_TRUE(contains(r.out, "-1e999")) << r.out;
  EXPECT_FALSE(contains(r.out, "not valid JSON")) << r.out;
}

TEST(CliRefusesBadInput, ANoOpActionWithTwoParametersIsRefusedAtLoad) {
  WorkshopCopy w("issue61-noop");
  json p = w.pack();
  p["roles"]["noop_action"] = "move";  // (move ?a ?from ?to)
  w.write_pack(p);
  const auto r = run(w.infer());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "roles.noop_action: action 'move' has 3 parameters")) << r.out;
}

TEST(CliRefusesBadInput, ARoleThatCannotActIsRefusedAtLoad) {
  WorkshopCopy w("issue61-principal");
  json p = w.pack();
  p["roles"]["principal"] = "rack";  // a station
  w.write_pack(p);
  const auto r = run(w.infer());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "roles.principal names 'rack', of type 'station'")) << r.out;
  EXPECT_TRUE(contains(r.out, "the roles must be agents")) << r.out;
}

TEST(CliRefusesBadInput, AGoalThatCanNeverHoldIsRefusedByInferBenchAndValidate) {
  WorkshopCopy w("issue61-goal");
  w.write("goals/definitions/table.pddl", "(and (made table) (not (made table)))\n");
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run(w.infer());
  EXPECT_LT(seconds_since(t0), 60);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "table.pddl: goal 'table' can never hold in problem 1")) << r.out;
  // The goal compiles to false: (made table) and its negation.
  EXPECT_TRUE(contains(r.out, "false in every state (it contradicts itself")) << r.out;
  // A goal no action can reach ((frozen ?a) is clips's own, never an effect): the same.
  w.write("goals/definitions/table.pddl", "(and (made table) (frozen human))\n");
  const auto b = run(clips() + " bench --dataset " + w.ds + " --plans 1.1.table -j 1");
  EXPECT_EQ(b.status, 3) << b.out;  // refused before any plan runs (the model reads every problem)
  EXPECT_TRUE(contains(b.out, "goal 'table' can never hold")) << b.out;
  EXPECT_TRUE(contains(b.out, "no sequence of actions makes (frozen human) true")) << b.out;
  const auto v = run(clips() + " validate --dataset " + w.ds);
  EXPECT_NE(v.status, 0) << v.out;
  EXPECT_TRUE(contains(v.out, "can never hold")) << v.out;
}

TEST(CliRefusesBadInput, CodeOfAnotherDomainIsNamed) {
  WorkshopCopy w("issue61-code");
  json p = w.pack();
  p["code"] = "doors-keys-gems";
  w.write_pack(p);
  const auto r = run(w.infer());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "code: \"doors-keys-gems\" is the compiled code of the paper's")) << r.out;
  EXPECT_FALSE(contains(r.out, "unknown function")) << r.out;
}

TEST(CliRefusesBadInput, FewShotAndCorpusErrorsAreInputErrors) {
  WorkshopCopy w("issue61-fewshot");
  // A few-shot line with a field missing, and one whose command the
  // language model cannot read (it was exit 6 at the first scoring, naming
  // "prompt example 11"): status 3 (input), naming file:line.
  const std::string original = testing::read_text(fs::path(w.ds) / "fewshot.tsv");
  for (const std::string& bad : {std::string("workshop\t99\t(pickup robot plank1)\n"),
                                 std::string("workshop\t99\t(pickup you plank1 where\tGet it.\tyes\n")}) {
    std::string fewshot = original;
    if (!fewshot.empty() && fewshot.back() != '\n') fewshot += '\n';
    fewshot += bad;
    const int line = static_cast<int>(std::count(fewshot.begin(), fewshot.end(), '\n'));
    w.write("fewshot.tsv", fewshot);
    const auto r = run(w.infer());
    EXPECT_EQ(r.status, 3) << bad << r.out;
    EXPECT_TRUE(contains(r.out, "fewshot.tsv:" + std::to_string(line))) << r.out;
  }
  // A corpus the pack names that does not exist.
  WorkshopCopy c("issue61-corpus");
  json p = c.pack();
  p["embedded_corpus"] = json::array({"no-such-corpus.tsv"});
  c.write_pack(p);
  const auto r = run(c.infer());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "no-such-corpus.tsv")) << r.out;
  EXPECT_TRUE(contains(r.out, "embedded_corpus")) << r.out;
}

TEST(CliRefusesBadInput, ACorpusLineErrorIsAnInputErrorNamingFileAndLine) {
  testing::TempDir tmp("issue61-corpus-line");
  std::ofstream(tmp.path / "mine.tsv") << "# a corpus\n(pickup you key1)\tGet the key.\n(pickup you key1 where\tOops.\n";
  lm::EmbeddedModelOptions o;
  o.data_dir = tmp.str();
  o.corpus_files = {"mine.tsv"};
  o.cache_dir = "off";
  try {
    lm::EmbeddedLanguageModel m(o);
    ADD_FAILURE() << "a malformed corpus line was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), (tmp.path / "mine.tsv").string() + ":3:")) << e.what();
  }
}

TEST(CliRefusesBadInput, AHugePackValueIsNotEchoedWhole) {
  WorkshopCopy w("issue61-huge");
  json p = w.pack();
  p["roles"]["noop_action"] = std::string(1 << 20, 'w');
  w.write_pack(p);
  const auto r = run(w.infer());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "roles.noop_action")) << r.out.substr(0, 300);
  EXPECT_TRUE(contains(r.out, "...")) << r.out.substr(0, 300);
  EXPECT_LT(r.out.size(), 4000u);
}

TEST(CliRefusesBadInput, ManyProfilesAndRepeatedSalientActionsAreRefusedQuickly) {
  WorkshopCopy w("issue61-profiles");
  json p = w.pack();
  json profiles = json::array();
  for (int i = 0; i < 200; ++i) profiles.push_back({{"name", "c" + std::to_string(i)}, {"default", 1 + i}});
  p["cost_profiles"] = json::array({{{"profiles", profiles}}});
  w.write_pack(p);
  auto t0 = std::chrono::steady_clock::now();
  auto r = run(w.infer());
  EXPECT_LT(seconds_since(t0), 10);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "cost_profiles[0].profiles: 200 profiles; at most 32")) << r.out;

  p = w.pack();
  p.erase("cost_profiles");
  json salient = json::array();
  for (int i = 0; i < 50; ++i) salient.push_back({{"action", "pickup"}, {"agent_arg", 1}, {"focal_arg", 2}});
  p["language"]["salient_actions"] = salient;
  w.write_pack(p);
  t0 = std::chrono::steady_clock::now();
  r = run(w.infer());
  EXPECT_LT(seconds_since(t0), 10);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "salient_actions[1].action: 'pickup' is already salient_actions[0]")) << r.out;
}

}  // namespace
}  // namespace clips::eval
