// issue 46 on the command line: limits that must hold (a sub-millisecond
// --lm-timeout, the multimodal method's requests, option bounds), inputs
// refused with their own exit status (URLs that are not http(s), FIFOs,
// a corrupt stimuli.json, Latin-1 names) and utterances echoed with their
// control characters escaped. Every command runs under `timeout`, so a
// regression is a failure, not a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "eval/support.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::eval {
namespace {

namespace fs = std::filesystem;
using lm::fake::FakeOpenAiServer;
using testing::contains;
using testing::run;

std::string clips() { return "timeout 120 " + testing::clips_binary(); }

TEST(CliHardening, LmTimeoutBelowAMillisecondStillTimesOut) {
  FakeOpenAiServer server;
  lm::fake::FakeFaults slow;
  slow.delay_ms = 3000;
  server.set_faults(slow);
  server.start();
  // 0.4 ms used to truncate to 0 ms, which libcurl reads as "no timeout":
  // the slow server then answered and the command succeeded.
  const auto r = run("CLIPS_LM_CACHE_DIR=off OPENAI_API_KEY=test " + clips() + " listen --dataset " +
                     testing::examples_dkg() + " --plan e1.1.keys --lm openai --lm-model fake --lm-base-url " +
                     server.base_url() + " --lm-timeout 0.0004");
  EXPECT_EQ(r.status, 6) << r.out;
  EXPECT_TRUE(contains(r.out, "timed out")) << r.out;
  EXPECT_TRUE(contains(r.out, "total timeout 1 ms")) << r.out;
  server.stop();
}

TEST(CliHardening, MultimodalAssistHonoursLmTimeout) {
  FakeOpenAiServer server;
  lm::fake::FakeFaults slow;
  slow.delay_ms = 3000;
  server.set_faults(slow);
  server.start();
  const auto r = run("OPENAI_API_KEY=test " + clips() + " assist --dataset " + testing::examples_dkg() +
                     " --plan e1.1.keys --method multimodal --json --lm-timeout 0.3 --chat-base-url " +
                     server.base_url());
  // The chat request times out after 0.3 s (and one retry) instead of
  // waiting the 3 s the server takes.
  EXPECT_TRUE(contains(r.out, "timed out")) << r.out;
  EXPECT_TRUE(contains(r.out, "total timeout 300 ms")) << r.out;
  server.stop();
}

TEST(CliHardening, BaseUrlsMustBeHttp) {
  const std::string listen = clips() + " listen --dataset " + testing::examples_dkg() + " --plan e1.1.keys";
  auto r = run(listen + " --lm-base-url ''");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "is not an http:// or https:// URL")) << r.out;
  r = run(listen + " --lm openai --lm-base-url file:///etc/passwd");
  EXPECT_EQ(r.status, 2) << r.out;
  r = run(clips() + " assist --dataset " + testing::examples_dkg() +
          " --plan e1.1.keys --method multimodal --chat-base-url ftp://example.org/");
  EXPECT_EQ(r.status, 2) << r.out;
  // From the environment: refused before any request (issue 61; libcurl is
  // also told to speak HTTP(S) only).
  r = run("CLIPS_LM_CACHE_DIR=off CLIPS_LM_BASE_URL=file:///etc/passwd OPENAI_API_KEY=test " + listen + " --lm openai");
  EXPECT_EQ(r.status, 6) << r.out;
  EXPECT_TRUE(contains(r.out, "is not an http:// or https:// URL ($CLIPS_LM_BASE_URL)")) << r.out;
}

TEST(CliHardening, OptionsThatCannotRunAreUsageErrors) {
  const std::string infer = clips() + " infer --dataset " + testing::examples_dkg() + " --plan e1.1.keys --particles 8";
  for (const std::string& cmd :
       {infer + " --rejuvenation-moves 1e9", infer + " --rejuvenation-moves 101", infer + " --proposal-groups 1000000000",
        clips() + " serve --stdio --session-threads 200", clips() + " serve --stdio --threads 100000",
        clips() + " serve --read-timeout 0", clips() + " serve --max-connections 0",
        clips() + " bench --dataset " + testing::examples_dkg() + " -j 100000 --out /nonexistent/x"}) {
    const auto r = run(cmd + " </dev/null");
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.out;
  }
}

TEST(CliHardening, FifoCorruptStimuliAndLatin1NamesAreInputErrors) {
  {
    testing::ExamplesCopy copy("issue46-fifo");
    fs::remove(copy.file("domain.pddl"));
    ASSERT_EQ(mkfifo(copy.file("domain.pddl").c_str(), 0600), 0);
    const auto r = run(clips() + " validate --dataset " + copy.ds);
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "domain.pddl: is not a regular file")) << r.out;
  }
  {
    testing::ExamplesCopy copy("issue46-stimuli");
    std::ofstream(copy.file("stimuli.json")) << "[{\"name\": 7";
    for (const std::string cmd : {" infer --plan e1.1.keys", " assist --plan e1.1.keys --method clips"}) {
      const auto r = run(clips() + cmd + " --dataset " + copy.ds);
      EXPECT_EQ(r.status, 3) << cmd << "\n" << r.out;
      EXPECT_TRUE(contains(r.out, "stimuli.json")) << r.out;
    }
    testing::TempDir out("issue46-bench");
    const auto b = run(clips() + " bench --no-progress -j 1 --methods clips --dataset " + copy.ds + " --out " + out.str());
    EXPECT_EQ(b.status, 3) << b.out;
    EXPECT_TRUE(contains(b.out, "stimuli.json")) << b.out;
  }
  {
    testing::ExamplesCopy copy("issue46-latin1");
    std::string text = testing::read_text(copy.file("problems/e1.pddl"));
    const size_t at = text.find("green - color");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, "kuchen\xfc ");
    std::ofstream(copy.file("problems/e1.pddl")) << text;
    auto r = run(clips() + " infer --json --dataset " + copy.ds + " --plan e1.1.keys");
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "problems/e1.pddl:5:")) << r.out;
    EXPECT_TRUE(contains(r.out, "is not valid UTF-8")) << r.out;
    EXPECT_FALSE(contains(r.out, "type_error")) << r.out;
    // validate names the file for each plan of that problem (and exits 1).
    r = run(clips() + " validate --dataset " + copy.ds);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL  e1.1.keys")) << r.out;
  }
}

TEST(CliHardening, UtterancesAreEchoedWithControlCharactersEscaped) {
  const auto r = run(clips() + " listen --dataset " + testing::examples_dkg() +
                     " --plan e1.1.keys --utterance \"$(printf '\\033[31mCan you get the red key?')\"");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "utterance: \"\\x1b[31mCan you get the red key?\"")) << r.out;
  EXPECT_FALSE(contains(r.out, "\x1b")) << r.out;
}

}  // namespace
}  // namespace clips::eval
