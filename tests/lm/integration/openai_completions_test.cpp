#include "lm/openai_completions_test.hpp"

namespace clips::lm {
namespace openai_completions_test {
// The 774 MB case of issue hardening: an endless stream ends at the default
// 16 MiB cap with an error naming the URL, not with memory filling up.
TEST_F(OpenAiCompletionsTest, EndlessReplyStopsAtTheDefaultCap) {
  FakeFaults f;
  f.reply = FakeReply::Endless;
  server.set_faults(f);
  auto o = options();
  o.http.total_timeout = 20000ms;
  OpenAiCompletionsModel m(o);
  const std::string err = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_NE(err.find(url()), std::string::npos) << err;
  EXPECT_NE(err.find(std::to_string(std::size_t{16} << 20) + " bytes"), std::string::npos) << err;
  EXPECT_EQ(server.completion_requests(), 1);
}

}  // namespace openai_completions_test

}  // namespace clips::lm
