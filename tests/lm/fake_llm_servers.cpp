#include "lm/fake_llm_servers.hpp"

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

#include <mutex>
#include <thread>

namespace clips::lm::fake {

using nlohmann::json;

namespace {

std::vector<std::string> tokens_of(const std::string& text) {
  std::vector<std::string> out;
  for (char c : text) {
    if (out.empty() || c == ' ' || c == '\n' || out.back() == "\n") out.emplace_back();
    out.back() += c;
  }
  return out;
}

std::vector<std::string> prompts_of(const json& body) {
  const json& p = body.at("prompt");
  std::vector<std::string> out;
  if (p.is_string()) out.push_back(p.get<std::string>());
  else
    for (const auto& x : p) out.push_back(x.get<std::string>());
  return out;
}

void reply_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

json completion(const json& choices, const json& body, const char* fingerprint) {
  json out = {{"id", "cmpl-fake"}, {"object", "text_completion"}, {"created", 1700000000},
              {"model", body.value("model", "m")}, {"choices", choices},
              {"usage", {{"prompt_tokens", 9}, {"completion_tokens", 1}, {"total_tokens", 10}}}};
  if (fingerprint) out["system_fingerprint"] = fingerprint;
  return out;
}

// llama.cpp's chat-style logprobs of one generated token.
json generated_logprobs() {
  return {{"content", json::array({{{"id", 5329}, {"token", " ok"}, {"logprob", -0.5}, {"bytes", {32, 111, 107}},
                                    {"top_logprobs", json::array()}}})}};
}

}  // namespace

struct FakeLlmServer::Impl {
  LlmFlavour flavour;
  httplib::Server server;
  std::thread thread;
  mutable std::mutex mutex;
  std::vector<json> requests;
  int port = -1;

  void record(const json& body) {
    std::lock_guard lock(mutex);
    requests.push_back(body);
  }

  void llama_old(const json& body, httplib::Response& res) {
    if (body.value("echo", false)) {
      reply_json(res, 500, {{"error", {{"code", 500}, {"message", "Only no echo is supported"}, {"type", "server_error"}}}});
      return;
    }
    json choices = json::array();
    std::size_t i = 0;
    for (const auto& p : prompts_of(body)) {
      (void)p;
      choices.push_back({{"text", " ok"}, {"index", i++}, {"logprobs", nullptr}, {"finish_reason", "length"}});
    }
    reply_json(res, 200, completion(choices, body, nullptr));
  }

  void llama_new(const json& body, httplib::Response& res) {
    json choices = json::array();
    std::size_t i = 0;
    for (const auto& p : prompts_of(body)) {
      (void)p;
      json c = {{"text", " ok"}, {"index", i++}, {"finish_reason", "length"}};
      c["logprobs"] = body.contains("logprobs") ? generated_logprobs() : json(nullptr);
      choices.push_back(c);
    }
    reply_json(res, 200, completion(choices, body, "b4600-fake"));
  }

  void llama_native(const json& body, httplib::Response& res) {
    json items = json::array();
    for (const auto& p : prompts_of(body)) {
      items.push_back({{"content", " ok"}, {"id_slot", 0}, {"stop", true}, {"model", "gguf"},
                       {"tokens_predicted", 1}, {"tokens_evaluated", tokens_of(p).size()},
                       {"completion_probabilities", json::array({{{"id", 5329}, {"token", " ok"}, {"logprob", -0.5}}})}});
    }
    // One prompt: one object; several: an array of them.
    reply_json(res, 200, body.at("prompt").is_string() || items.size() == 1 ? items[0] : items);
  }

  void ollama(const json& body, httplib::Response& res) {
    if (!body.at("prompt").is_string()) {
      reply_json(res, 400, {{"error", {{"message", "json: cannot unmarshal array into Go struct field "
                                                    "CompletionRequest.prompt of type string"},
                                       {"type", "invalid_request_error"}, {"param", nullptr}, {"code", nullptr}}}});
      return;
    }
    const json choices = json::array({{{"text", " ok"}, {"index", 0}, {"finish_reason", "stop"}}});
    reply_json(res, 200, completion(choices, body, "fp_ollama"));
  }

  void vllm(const json& body, httplib::Response& res) {
    if (body.value("max_tokens", 16) < 1) {
      reply_json(res, 400, {{"object", "error"}, {"message", "max_tokens must be at least 1, got 0."},
                            {"type", "BadRequestError"}, {"code", 400}});
      return;
    }
    json choices = json::array();
    std::size_t i = 0;
    for (const auto& p : prompts_of(body)) {
      const auto toks = tokens_of(p);
      json c = {{"index", i++}, {"text", " ok"}, {"logprobs", nullptr}, {"finish_reason", "length"}};
      if (body.contains("prompt_logprobs")) {
        json plp = json::array({nullptr});
        for (std::size_t k = 1; k < toks.size(); ++k)
          plp.push_back({{std::to_string(1000 + k), {{"logprob", logprob_of(toks[k])}, {"rank", 1}, {"decoded_token", toks[k]}}}});
        c["prompt_logprobs"] = plp;
      } else if (body.value("echo", false) && body.contains("logprobs")) {
        json offsets = json::array(), lps = json::array(), strs = json::array();
        std::size_t at = 0;
        for (const auto& t : toks) {
          offsets.push_back(at);
          lps.push_back(offsets.size() == 1 ? json(nullptr) : json(logprob_of(t)));
          strs.push_back(t);
          at += t.size();
        }
        offsets.push_back(at);  // the generated token (max_tokens=1)
        lps.push_back(-0.5);
        strs.push_back(" ok");
        c["text"] = p + " ok";
        c["logprobs"] = {{"text_offset", offsets}, {"token_logprobs", lps}, {"tokens", strs}, {"top_logprobs", nullptr}};
      }
      choices.push_back(c);
    }
    reply_json(res, 200, completion(choices, body, nullptr));
  }
};

FakeLlmServer::FakeLlmServer(LlmFlavour flavour) : impl_(std::make_unique<Impl>()) {
  impl_->flavour = flavour;
  auto handle = [this](const httplib::Request& req, httplib::Response& res) {
    const json body = json::parse(req.body, nullptr, false);
    if (body.is_discarded() || !body.is_object() || !body.contains("prompt")) {
      reply_json(res, 400, {{"error", {{"message", "bad request"}}}});
      return;
    }
    impl_->record(body);
    switch (impl_->flavour) {
      case LlmFlavour::LlamaCppOld: return impl_->llama_old(body, res);
      case LlmFlavour::LlamaCppNew: return impl_->llama_new(body, res);
      case LlmFlavour::LlamaCppNative: return impl_->llama_native(body, res);
      case LlmFlavour::Ollama: return impl_->ollama(body, res);
      case LlmFlavour::Vllm: return impl_->vllm(body, res);
    }
  };
  if (flavour == LlmFlavour::LlamaCppNative) {
    impl_->server.Post("/completion", handle);
    impl_->server.Post("/completions", handle);
  } else {
    impl_->server.Post("/v1/completions", handle);
  }
  impl_->port = impl_->server.bind_to_any_port("127.0.0.1");
  impl_->thread = std::thread([this] { impl_->server.listen_after_bind(); });
}

FakeLlmServer::~FakeLlmServer() {
  impl_->server.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

std::string FakeLlmServer::base_url() const {
  const std::string host = "http://127.0.0.1:" + std::to_string(impl_->port);
  return impl_->flavour == LlmFlavour::LlamaCppNative ? host : host + "/v1";
}

std::vector<json> FakeLlmServer::requests() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->requests;
}

double FakeLlmServer::logprob_of(const std::string& token) { return -0.25 * static_cast<double>(token.size()) - 0.5; }

double FakeLlmServer::continuation_logprob(const std::string& prompt, const std::string& continuation) {
  double sum = 0;
  std::size_t at = 0;
  for (const auto& t : tokens_of(prompt + continuation)) {
    if (at >= prompt.size()) sum += logprob_of(t);
    at += t.size();
  }
  return sum;
}

}  // namespace clips::lm::fake
