// OpenAiCompletionsModel with vLLM's prompt_logprobs, against a loopback fake
// that answers /v1/completions in vLLM's shape: choices[i].prompt_logprobs, a
// list with null for the first prompt token and then, per token,
// {"<token id>": {"logprob", "rank", "decoded_token"}} with the prompt's token
// and, when it was not the most likely, the rank-1 alternative. The fake
// refuses max_tokens=0 as vLLM does, and echo (it must not be asked for).

// Debian builds libcpp-httplib with these switches; the declarations must see
// the same ones or the class layouts disagree with the shared library.
#ifndef CPPHTTPLIB_OPENSSL_SUPPORT
#define CPPHTTPLIB_OPENSSL_SUPPORT
#endif
#ifndef CPPHTTPLIB_ZLIB_SUPPORT
#define CPPHTTPLIB_ZLIB_SUPPORT
#endif
#ifndef CPPHTTPLIB_BROTLI_SUPPORT
#define CPPHTTPLIB_BROTLI_SUPPORT
#endif
#include <httplib.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "lm/openai_model.hpp"

namespace clips::lm {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;

// The fake's tokens: a space starts a token, "\n" is one; so the pieces
// spell the text exactly.
std::vector<std::string> tokens_of(const std::string& text) {
  std::vector<std::string> out;
  for (char c : text) {
    if (out.empty() || c == ' ' || c == '\n' || out.back() == "\n") out.emplace_back();
    out.back() += c;
  }
  return out;
}

// The fake model: a token's log-prob depends on its text only.
double logprob_of(const std::string& token) { return -0.25 * static_cast<double>(token.size()) - 0.5; }
// Every third token was not the model's first choice (rank 3, with a rank-1 alternative).
bool not_first_choice(std::size_t k) { return k % 3 == 2; }

class VllmFake {
 public:
  bool mangle_tokens = false;  // decoded tokens that do not spell the prompt
  bool null_inside = false;    // a null entry in the middle
  bool answer_with_echo = false;  // a server that ignores prompt_logprobs and echoes (OpenAI's shape)
  std::vector<json> requests;

  VllmFake() {
    server_.Post("/v1/completions", [this](const httplib::Request& req, httplib::Response& res) {
      const json body = json::parse(req.body);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        requests.push_back(body);
      }
      if (body.value("max_tokens", 16) < 1) {
        res.status = 400;
        res.set_content(R"({"object":"error","message":"max_tokens must be at least 1, got 0.","type":"BadRequestError"})",
                        "application/json");
        return;
      }
      json choices = json::array();
      std::size_t i = 0;
      for (const auto& p : body.at("prompt")) {
        const auto toks = tokens_of(p.get<std::string>());
        json choice = {{"index", i++}, {"text", " ok"}, {"logprobs", nullptr}, {"finish_reason", "length"},
                       {"stop_reason", nullptr}};
        if (answer_with_echo) {
          json offsets = json::array(), lps = json::array(), strs = json::array();
          std::size_t at = 0;
          for (const auto& t : toks) {
            offsets.push_back(at);
            lps.push_back(logprob_of(t));
            strs.push_back(t);
            at += t.size();
          }
          lps[0] = nullptr;
          choice["logprobs"] = {{"text_offset", offsets}, {"token_logprobs", lps}, {"tokens", strs}};
        } else {
          json plp = json::array();
          plp.push_back(nullptr);
          for (std::size_t k = 1; k < toks.size(); ++k) {
            if (null_inside && k == toks.size() - 2) {
              plp.push_back(nullptr);
              continue;
            }
            json entry = json::object();
            const std::string decoded = mangle_tokens && k == toks.size() - 1 ? toks[k] + "x" : toks[k];
            entry[std::to_string(1000 + k)] = {
                {"logprob", logprob_of(toks[k])}, {"rank", not_first_choice(k) ? 3 : 1}, {"decoded_token", decoded}};
            if (not_first_choice(k))
              entry["7"] = {{"logprob", -0.01}, {"rank", 1}, {"decoded_token", " the"}};
            plp.push_back(entry);
          }
          choice["prompt_logprobs"] = plp;
        }
        choices.push_back(choice);
      }
      json reply = {{"id", "cmpl-fake"}, {"object", "text_completion"}, {"model", body.at("model")},
                    {"choices", choices}, {"usage", {{"prompt_tokens", 1}, {"completion_tokens", 1}}}};
      res.set_content(reply.dump(), "application/json");
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
  }
  ~VllmFake() {
    server_.stop();
    thread_.join();
  }
  std::string base_url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/v1"; }

 private:
  httplib::Server server_;
  std::thread thread_;
  std::mutex mutex_;
  int port_ = -1;
};

const std::string kPrompt =
    "Input: (pickup you key1)\nOutput: Get the key over there.\nInput: (handover you me key1)\nOutput:";
const std::string kUtterance = " Can you pass me the red key?\n";

// The continuation's tokens' log-probs (the fake's tokens never straddle the boundary here).
double expected(const std::string& prompt, const std::string& continuation) {
  double sum = 0;
  std::size_t at = 0;
  for (const auto& t : tokens_of(prompt + continuation)) {
    if (at + t.size() > prompt.size()) sum += logprob_of(t);
    at += t.size();
  }
  return sum;
}

OpenAiCompletionsOptions options(const VllmFake& fake, std::optional<bool> prompt_logprobs = true) {
  OpenAiCompletionsOptions o;
  o.base_url = fake.base_url();
  o.model = "fake-vllm";
  o.api_key = "";
  o.prompt_logprobs = prompt_logprobs;
  o.http.connect_timeout = 500ms;
  o.http.total_timeout = 2000ms;
  o.http.max_retries = 0;
  return o;
}

TEST(VllmPromptLogprobs, ScoresTheContinuationFromPromptLogprobs) {
  VllmFake fake;
  OpenAiCompletionsModel m(options(fake));
  EXPECT_TRUE(m.using_prompt_logprobs());
  const std::vector<ScoreRequest> batch = {{kPrompt, kUtterance}, {kPrompt, " Get the red key.\n"},
                                           {"Input: (wait me)\nOutput:", " Wait there.\n"}};
  const auto scores = m.score(batch);
  ASSERT_EQ(scores.size(), 3u);
  for (std::size_t i = 0; i < batch.size(); ++i)
    EXPECT_NEAR(scores[i], expected(batch[i].prompt, batch[i].continuation), 1e-12) << i;
  EXPECT_NE(scores[0], scores[1]);
  // vLLM refuses max_tokens=0: asked once, then max_tokens=1 for the rest of the run.
  EXPECT_TRUE(m.using_max_tokens_fallback());
  ASSERT_EQ(fake.requests.size(), 2u);
  EXPECT_EQ(fake.requests[0]["max_tokens"], 0);
  EXPECT_EQ(fake.requests[1]["max_tokens"], 1);
  for (const auto& r : fake.requests) {
    EXPECT_EQ(r["prompt_logprobs"], 1);
    EXPECT_FALSE(r.contains("echo"));
    EXPECT_FALSE(r.contains("logprobs"));
  }
}

TEST(VllmPromptLogprobs, TheTemperatureDividesTheScore) {
  VllmFake fake;
  auto o = options(fake);
  o.temperature = 2.0;
  OpenAiCompletionsModel m(o);
  EXPECT_NEAR(m.score({{kPrompt, kUtterance}})[0], expected(kPrompt, kUtterance) / 2.0, 1e-12);
}

TEST(VllmPromptLogprobs, OffByDefaultAndOnThroughTheEnvironment) {
  VllmFake fake;
  fake.answer_with_echo = true;
  ::unsetenv("CLIPS_LM_PROMPT_LOGPROBS");
  OpenAiCompletionsModel plain(options(fake, std::nullopt));
  EXPECT_FALSE(plain.using_prompt_logprobs());
  // The echo protocol, same numbers from the same model.
  EXPECT_NEAR(plain.score({{kPrompt, kUtterance}})[0], expected(kPrompt, kUtterance), 1e-12);
  EXPECT_EQ(fake.requests.back()["echo"], true);
  EXPECT_FALSE(fake.requests.back().contains("prompt_logprobs"));
  ::setenv("CLIPS_LM_PROMPT_LOGPROBS", "on", 1);
  OpenAiCompletionsModel from_env(options(fake, std::nullopt));
  ::unsetenv("CLIPS_LM_PROMPT_LOGPROBS");
  EXPECT_TRUE(from_env.using_prompt_logprobs());
  // An explicit option wins over the environment.
  ::setenv("CLIPS_LM_PROMPT_LOGPROBS", "1", 1);
  OpenAiCompletionsModel off(options(fake, false));
  ::unsetenv("CLIPS_LM_PROMPT_LOGPROBS");
  EXPECT_FALSE(off.using_prompt_logprobs());
}

std::string error_of(VllmFake& fake) {
  OpenAiCompletionsModel m(options(fake));
  try {
    m.score({{kPrompt, kUtterance}});
  } catch (const LmError& e) {
    return e.what();
  }
  return "";
}

TEST(VllmPromptLogprobs, BrokenRepliesAreNamedErrors) {
  VllmFake fake;
  fake.mangle_tokens = true;
  const std::string mangled = error_of(fake);
  EXPECT_NE(mangled.find("choices[0].prompt_logprobs"), std::string::npos) << mangled;
  EXPECT_NE(mangled.find("do not spell the prompt"), std::string::npos) << mangled;
  fake.mangle_tokens = false;
  fake.null_inside = true;
  const std::string null_inside = error_of(fake);
  EXPECT_NE(null_inside.find("is null inside the continuation"), std::string::npos) << null_inside;
}

TEST(VllmPromptLogprobs, ParsesVllmsDocumentedShapeDirectly) {
  // A token straddling the prompt's end counts whole; the prompt's token is
  // the entry of highest rank; the first entry is null.
  const std::string prompt = "Output:", continuation = " Go\n";
  const json plp = json::parse(R"([
    null,
    {"25": {"logprob": -1.5, "rank": 1, "decoded_token": "put"}},
    {"9": {"logprob": -0.25, "rank": 1, "decoded_token": ": Go"}, "30": {"logprob": -2.0, "rank": 4, "decoded_token": ":"}},
    {"13": {"logprob": -0.75, "rank": 1, "decoded_token": "\n"}}
  ])");
  // ":" (rank 4) is the prompt's token, so the text is "Out" + "put" + ":" ... which does not end with " Go\n":
  EXPECT_THROW(detail::sum_prompt_logprobs(plp, prompt, continuation, "p"), LmError);
  const json good = json::parse(R"([
    null,
    {"25": {"logprob": -1.5, "rank": 1, "decoded_token": "put"}},
    {"9": {"logprob": -0.25, "rank": 2, "decoded_token": ": Go"}, "30": {"logprob": -2.0, "rank": 1, "decoded_token": ":"}},
    {"13": {"logprob": -0.75, "rank": 1, "decoded_token": "\n"}}
  ])");
  EXPECT_DOUBLE_EQ(detail::sum_prompt_logprobs(good, prompt, continuation, "p"), -0.25 - 0.75);
  EXPECT_THROW(detail::sum_prompt_logprobs(json::object(), prompt, continuation, "p"), LmError);
}

}  // namespace
}  // namespace clips::lm
