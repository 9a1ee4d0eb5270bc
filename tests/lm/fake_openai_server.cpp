#include "lm/fake_openai_server.hpp"

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

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lm/base64.hpp"

namespace clips::lm::fake {

using nlohmann::json;

namespace {

std::size_t chars(const std::string& s, std::size_t begin, std::size_t end) {
  std::size_t n = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) ++n;
  }
  return n;
}

bool is_word_byte(unsigned char c) { return std::isalnum(c) || c == '_' || c == '\'' || c >= 0x80; }

json error_body(const std::string& message, const std::string& type) {
  return {{"error", {{"message", message}, {"type", type}, {"param", nullptr}, {"code", nullptr}}}};
}

bool is_png_data_url(const std::string& url) {
  static const std::string prefix = "data:image/png;base64,";
  if (url.rfind(prefix, 0) != 0) return false;
  auto bytes = base64_decode(std::string_view(url).substr(prefix.size()));
  static const std::uint8_t sig[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  return bytes && bytes->size() >= 8 && std::equal(sig, sig + 8, bytes->begin());
}

}  // namespace

struct FakeOpenAiServer::Impl {
  httplib::Server server;
  std::thread thread;
  std::atomic<bool> stopping{false};

  mutable std::mutex mutex;  // guards everything below
  FakeFaults faults;
  Scorer scorer;
  ChatRule chat_rule;
  int completion_requests = 0;
  int chat_requests = 0;
  std::vector<std::size_t> prompts_per_request;
  std::vector<std::optional<std::string>> auth_headers;
  json last_completion_body;
  json last_chat_body;
};

FakeOpenAiServer::FakeOpenAiServer() : impl_(std::make_unique<Impl>()) {}

FakeOpenAiServer::~FakeOpenAiServer() { stop(); }

std::string FakeOpenAiServer::base_url() const {
  return "http://127.0.0.1:" + std::to_string(port_) + "/v1";
}

void FakeOpenAiServer::set_faults(const FakeFaults& faults) {
  std::lock_guard lock(impl_->mutex);
  impl_->faults = faults;
}

void FakeOpenAiServer::set_scorer(Scorer scorer) {
  std::lock_guard lock(impl_->mutex);
  impl_->scorer = std::move(scorer);
}

void FakeOpenAiServer::set_chat_rule(ChatRule rule) {
  std::lock_guard lock(impl_->mutex);
  impl_->chat_rule = std::move(rule);
}

int FakeOpenAiServer::completion_requests() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->completion_requests;
}
int FakeOpenAiServer::chat_requests() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->chat_requests;
}
std::vector<std::size_t> FakeOpenAiServer::prompts_per_request() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->prompts_per_request;
}
std::vector<std::optional<std::string>> FakeOpenAiServer::authorization_headers() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->auth_headers;
}
json FakeOpenAiServer::last_completion_body() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->last_completion_body;
}
json FakeOpenAiServer::last_chat_body() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->last_chat_body;
}

// Words keep their leading spaces; punctuation and "\n" are tokens of their own.
std::vector<FakeToken> FakeOpenAiServer::tokenize(const std::string& text) {
  std::vector<FakeToken> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t begin = i;
    while (i < text.size() && text[i] == ' ') ++i;  // leading spaces
    const auto c = static_cast<unsigned char>(i < text.size() ? text[i] : '\0');
    if (i < text.size() && is_word_byte(c)) {
      while (i < text.size() && is_word_byte(static_cast<unsigned char>(text[i]))) ++i;
    } else if (i < text.size() && text[i] != '\n') {
      ++i;  // one punctuation character, with any spaces before it: " ?"
    } else if (begin == i && i < text.size()) {
      ++i;  // "\n" alone
    }  // else: spaces right before "\n" or the end form their own token
    out.push_back({text.substr(begin, i - begin), chars(text, 0, begin)});
  }
  return out;
}

double FakeOpenAiServer::unigram_logprob(const std::string& token) {
  // Deterministic and token-dependent: longer tokens are rarer, plus a hash jitter.
  std::uint32_t h = 2166136261u;
  for (unsigned char c : token) h = (h ^ c) * 16777619u;
  return -(0.5 + 0.3 * static_cast<double>(token.size()) + 0.1 * static_cast<double>(h % 7));
}

std::vector<double> FakeOpenAiServer::token_logprobs(const std::string& text) const {
  Scorer scorer;
  {
    std::lock_guard lock(impl_->mutex);
    scorer = impl_->scorer;
  }
  const auto tokens = tokenize(text);
  std::vector<double> lps(tokens.size());
  for (std::size_t k = 0; k < tokens.size(); ++k) lps[k] = unigram_logprob(tokens[k].text);
  if (!lps.empty()) lps[0] = std::numeric_limits<double>::quiet_NaN();

  // With a scorer, the continuation after the last "\nOutput:" gets its exact total.
  const auto marker = text.rfind("\nOutput:");
  if (scorer && marker != std::string::npos) {
    const std::size_t split = marker + 8;
    const std::size_t split_chars = chars(text, 0, split);
    std::vector<std::size_t> cont;
    for (std::size_t k = 1; k < tokens.size(); ++k) {
      if (tokens[k].offset >= split_chars) cont.push_back(k);
    }
    if (!cont.empty()) {
      const double total = scorer(text.substr(0, split), text.substr(split));
      for (std::size_t k : cont) lps[k] = total / static_cast<double>(cont.size());
    }
  }
  return lps;
}

namespace {

// Writes `body` according to the reply fault that concerns transport/syntax.
// Returns false when the fault is about content and the caller must build it.
bool apply_body_fault(FakeReply reply, const std::string& body, httplib::Response& res,
                      const std::atomic<bool>& stopping) {
  switch (reply) {
    case FakeReply::Endless:
      // A JSON prefix, then one string that never closes, 64 KiB at a time.
      res.set_chunked_content_provider("application/json", [&stopping](std::size_t offset, httplib::DataSink& sink) {
        static const std::string filler(std::size_t{1} << 16, 'x');
        if (stopping) return false;
        if (offset == 0) {
          const std::string head = R"({"choices": [{"index": 0, "text": ")";
          return sink.write(head.data(), head.size());
        }
        return sink.write(filler.data(), filler.size());
      });
      return true;
    case FakeReply::MalformedJson:
      res.set_content("{\"choices\": [ {\"index\": 0,, oops", "application/json");
      return true;
    case FakeReply::HugeNumber: {
      std::string text = body;
      const std::string key = "\"token_logprobs\":[";
      const std::size_t at = text.find(key);
      if (at == std::string::npos) return false;
      const std::size_t start = at + key.size(), end = text.find_first_of(",]", start);
      text.replace(start, end - start, "-1e999");
      res.set_content(text, "application/json");
      return true;
    }
    case FakeReply::CutJson:
      res.set_content(body.substr(0, body.size() / 2), "application/json");
      return true;
    case FakeReply::ShortBody: {
      auto shared = std::make_shared<std::string>(body);
      res.set_content_provider(
          shared->size() + 100, "application/json",
          [shared](std::size_t offset, std::size_t, httplib::DataSink& sink) {
            if (offset < shared->size()) {
              sink.write(shared->data() + offset, shared->size() - offset);
              return true;
            }
            return false;  // abort: fewer bytes than Content-Length promised
          });
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

void FakeOpenAiServer::start() {
  if (port_ > 0) return;
  Impl& s = *impl_;
  s.stopping = false;

  // Shared preamble: bookkeeping, delay and injected failures. Returns the
  // faults to use, or nullopt when the request has been answered already.
  auto preamble = [&s](const httplib::Request& req, httplib::Response& res, bool chat,
                             json& body) -> std::optional<FakeFaults> {
    body = json::parse(req.body, nullptr, false);
    FakeFaults f;
    {
      std::lock_guard lock(s.mutex);
      (chat ? s.chat_requests : s.completion_requests)++;
      s.auth_headers.push_back(req.has_header("Authorization")
                                   ? std::optional<std::string>(req.get_header_value("Authorization"))
                                   : std::nullopt);
      if (chat) {
        s.last_chat_body = body;
      } else {
        s.last_completion_body = body;
        std::size_t n = 0;
        if (body.is_object() && body.contains("prompt")) {
          n = body["prompt"].is_array() ? body["prompt"].size() : 1;
        }
        s.prompts_per_request.push_back(n);
      }
      f = s.faults;
      if (s.faults.fail_first > 0) --s.faults.fail_first;
    }
    // Sleep in slices so stop() is not held up by a "slow" reply.
    for (int waited = 0; waited < f.delay_ms && !s.stopping; waited += 10) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (f.fail_first > 0) {
      res.status = f.fail_status;
      if (!f.retry_after.empty()) res.set_header("Retry-After", f.retry_after);
      res.set_content(error_body("injected failure " + std::to_string(f.fail_status), "server_error").dump(),
                      "application/json");
      return std::nullopt;
    }
    if (body.is_discarded() || !body.is_object()) {
      res.status = 400;
      res.set_content(error_body("request body is not a JSON object", "invalid_request_error").dump(),
                      "application/json");
      return std::nullopt;
    }
    return f;
  };

  s.server.Post("/v1/completions", [this, preamble](const httplib::Request& req, httplib::Response& res) {
    json body;
    auto faults = preamble(req, res, false, body);
    if (!faults) return;
    const FakeFaults& f = *faults;
    const int max_tokens = body.value("max_tokens", 16);
    const bool echo = body.value("echo", false);
    if (f.reject_max_tokens_zero && max_tokens == 0) {
      res.status = 400;
      res.set_content(json{{"object", "error"},
                           {"message", "max_tokens must be at least 1, got 0."},
                           {"type", "BadRequestError"},
                           {"param", nullptr},
                           {"code", 400}}
                          .dump(),
                      "application/json");
      return;
    }
    std::vector<std::string> prompts;
    if (body["prompt"].is_string()) {
      prompts.push_back(body["prompt"].get<std::string>());
    } else {
      for (const auto& p : body["prompt"]) prompts.push_back(p.get<std::string>());
    }

    json choices = json::array();
    for (std::size_t i = 0; i < prompts.size(); ++i) {
      const std::string& text = prompts[i];
      auto tokens = tokenize(text);
      auto lps = token_logprobs(text);
      json toks = json::array(), logps = json::array(), offs = json::array(), tops = json::array();
      if (echo) {
        for (std::size_t k = 0; k < tokens.size(); ++k) {
          toks.push_back(tokens[k].text);
          offs.push_back(tokens[k].offset);
          if (std::isnan(lps[k])) {
            logps.push_back(nullptr);
            tops.push_back(nullptr);
          } else {
            logps.push_back(lps[k]);
            tops.push_back({{tokens[k].text, lps[k]}});
          }
        }
      }
      std::string generated;
      const std::size_t end = chars(text, 0, text.size());
      const int n_generated = (f.reply == FakeReply::NoEcho) ? std::max(1, max_tokens) : max_tokens;
      if (f.reply == FakeReply::NoEcho) toks = logps = offs = tops = json::array();
      for (int g = 0; g < n_generated; ++g) {
        toks.push_back(kGeneratedToken);
        offs.push_back(end + generated.size());
        logps.push_back(kGeneratedLogprob);
        tops.push_back({{kGeneratedToken, kGeneratedLogprob}});
        generated += kGeneratedToken;
      }
      json logprobs = {{"tokens", toks}, {"token_logprobs", logps}, {"text_offset", offs}, {"top_logprobs", tops}};
      if (i == f.damaged_choice) {
        if (f.reply == FakeReply::MissingTokenLogprobs) logprobs.erase("token_logprobs");
        if (f.reply == FakeReply::MissingTextOffset) logprobs.erase("text_offset");
        if (f.reply == FakeReply::NullTokenLogprob && !logprobs["token_logprobs"].empty()) {
          logprobs["token_logprobs"].back() = nullptr;
        }
      }
      json choice = {{"index", i},
                     {"text", (echo ? text : std::string()) + generated},
                     {"logprobs", logprobs},
                     {"finish_reason", "length"}};
      if (i == f.damaged_choice && f.reply == FakeReply::MissingLogprobs) choice.erase("logprobs");
      choices.push_back(choice);
    }
    if (f.reverse_choices) std::reverse(choices.begin(), choices.end());
    if (f.reply == FakeReply::WrongChoiceCount && !choices.empty()) choices.erase(choices.end() - 1);

    json reply = {{"id", "cmpl-fake"}, {"object", "text_completion"}, {"model", body.value("model", "")},
                  {"choices", choices}};
    if (f.reply == FakeReply::MissingChoices) reply.erase("choices");
    const std::string text = reply.dump();
    if (!apply_body_fault(f.reply, text, res, impl_->stopping)) res.set_content(text, "application/json");
  });

  s.server.Post("/v1/chat/completions", [preamble, &s](const httplib::Request& req, httplib::Response& res) {
    json body;
    auto faults = preamble(req, res, true, body);
    if (!faults) return;
    const FakeFaults& f = *faults;
    // Deterministic answer: a JSON summary of what was asked.
    std::string text;
    int images = 0;
    bool images_valid = true;
    for (const auto& m : body.value("messages", json::array())) {
      const json& content = m["content"];
      if (content.is_string()) text += content.get<std::string>() + "\n";
      if (!content.is_array()) continue;
      for (const auto& part : content) {
        if (part.value("type", "") == "text") text += part.value("text", "") + "\n";
        if (part.value("type", "") == "image_url") {
          ++images;
          images_valid = images_valid && is_png_data_url(part["image_url"].value("url", ""));
        }
      }
    }
    json answer = {{"model", body.value("model", "")},
                   {"text", text},
                   {"images", images},
                   {"images_valid", images_valid},
                   {"json_mode", body.contains("response_format")}};
    ChatRule rule;
    {
      std::lock_guard lock(s.mutex);
      rule = s.chat_rule;
    }
    json message = {{"role", "assistant"}, {"content", rule ? rule(body) : answer.dump()}};
    if (f.reply == FakeReply::NonJsonAnswer) message["content"] = "Sure! Here it is: {oops";
    if (f.reply == FakeReply::MissingContent) {
      message["content"] = nullptr;
      message["refusal"] = "I cannot help with that.";
    }
    json reply = {{"id", "chatcmpl-fake"},
                  {"object", "chat.completion"},
                  {"choices", json::array({{{"index", 0}, {"message", message}, {"finish_reason", "stop"}}})}};
    if (f.reply == FakeReply::MissingChoices) reply.erase("choices");
    const std::string out = reply.dump();
    if (!apply_body_fault(f.reply, out, res, s.stopping)) res.set_content(out, "application/json");
  });

  // Without TCP_NODELAY, header and body writes on a reused connection meet
  // the client's delayed ACK and every reply takes ~40 ms longer.
  s.server.set_tcp_nodelay(true);
  port_ = s.server.bind_to_any_port("127.0.0.1");
  if (port_ <= 0) throw std::runtime_error("fake server: cannot bind 127.0.0.1");
  s.thread = std::thread([&s] { s.server.listen_after_bind(); });
}

void FakeOpenAiServer::stop() {
  if (port_ <= 0) return;
  impl_->stopping = true;
  impl_->server.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
  port_ = -1;
}

}  // namespace clips::lm::fake
