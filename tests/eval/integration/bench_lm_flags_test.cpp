// `clips bench` takes its language model through the same --lm flags as the
// other subcommands: --lm-timeout is honoured, not accepted and ignored.
#include <gtest/gtest.h>

#include <chrono>

#include "eval/support.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::eval {
namespace {

using lm::fake::FakeOpenAiServer;

TEST(BenchLmFlags, TimeoutIsHonoured) {
  FakeOpenAiServer server;
  lm::fake::FakeFaults slow;
  slow.delay_ms = 4000;  // every answer takes 4 s
  server.set_faults(slow);
  server.start();
  testing::TempDir tmp("bench-lm");
  const std::string cmd = "CLIPS_LM_CACHE_DIR=off " + testing::clips_binary() + " bench --dataset " +
                          testing::examples_dkg() + " --plans e1.1.keys --methods clips --no-progress -j 1" +
                          " --lm openai --lm-base-url " + server.base_url() + " --lm-model fake --lm-timeout 0.5" +
                          " --out " + (tmp.path / "out").string();
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = testing::run(cmd);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The plan fails on the language model (timed out), well before one 4 s answer per try.
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("time"), std::string::npos) << r.out;
  EXPECT_LT(seconds, 3.9) << r.out;
}

}  // namespace
}  // namespace clips::eval
