#pragma once
// The includes, helpers and fixtures of the lm tests in openai_completions_test.cpp, shared by
// the files of that name in tests/lm/ and its label folders
// (docs/testing.md, "Labels").
// OpenAiCompletionsModel against the loopback fake server: exact slicing,
// batching, the max_tokens fallback, retries, timeouts and malformed replies.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <nlohmann/json.hpp>

#include "lm/openai_model.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::lm {
namespace openai_completions_test {

using fake::FakeFaults;
using fake::FakeOpenAiServer;
using fake::FakeReply;
using nlohmann::json;
using namespace std::chrono_literals;

const std::string kPrompt =
    "Input: (pickup you key1)\nOutput: Get the key over there.\nInput: (handover you me key1)\nOutput:";
const std::string kUtterance = " Can you pass me the red key?\n";

// What the fake server's default model gives the continuation tokens.
double expected_sum(const std::string& prompt, const std::string& continuation) {
  const auto tokens = FakeOpenAiServer::tokenize(prompt + continuation);
  double sum = 0;
  for (const auto& t : tokens) {
    if (t.offset >= prompt.size()) sum += FakeOpenAiServer::unigram_logprob(t.text);
  }
  return sum;
}

class OpenAiCompletionsTest : public ::testing::Test {
 protected:
  void SetUp() override { server.start(); }
  void TearDown() override { server.stop(); }

  OpenAiCompletionsOptions options() const {
    OpenAiCompletionsOptions o;
    o.base_url = server.base_url();
    o.model = "fake-model";
    o.api_key = "";
    o.http.connect_timeout = 200ms;
    o.http.total_timeout = 500ms;
    o.http.max_retries = 2;
    o.http.backoff_initial = 5ms;
    o.http.backoff_max = 20ms;
    return o;
  }
  std::string url() const { return server.base_url() + "/completions"; }

  // Runs a one-pair score and returns the LmError message ("" if none).
  std::string error_of(OpenAiCompletionsModel& m, std::vector<ScoreRequest> batch) {
    try {
      m.score(batch);
    } catch (const LmError& e) {
      return e.what();
    }
    return "";
  }

  FakeOpenAiServer server;
};

struct MalformedCase {
  FakeReply reply;
  std::size_t damaged;
  std::string expected;
};

// Sets environment variables for one test and restores them afterwards.
class EnvGuard {
 public:
  void set(const char* name, const char* value) {
    const char* old = std::getenv(name);
    saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
    if (value) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~EnvGuard() {
    for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
      if (it->second) {
        ::setenv(it->first.c_str(), it->second->c_str(), 1);
      } else {
        ::unsetenv(it->first.c_str());
      }
    }
  }

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

// --- the slicing rule on hand-written replies --------------------------------

double slice(const json& lp, const std::string& prompt, const std::string& cont) {
  return detail::sum_continuation_logprobs(lp, prompt, cont, "choices[0].logprobs");
}

std::string slice_error(const json& lp, const std::string& prompt, const std::string& cont) {
  try {
    slice(lp, prompt, cont);
  } catch (const LmError& e) {
    return e.what();
  }
  return "";
}

}  // namespace openai_completions_test
using namespace openai_completions_test;
}  // namespace clips::lm
