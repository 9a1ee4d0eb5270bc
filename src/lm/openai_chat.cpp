#include "lm/openai_chat.hpp"

#include <nlohmann/json.hpp>
#include <utility>

#include "lm/base64.hpp"

namespace clips::lm {

using nlohmann::json;

ChatPart ChatPart::from_text(std::string text) {
  ChatPart p;
  p.kind = Kind::Text;
  p.text = std::move(text);
  return p;
}

ChatPart ChatPart::from_png(std::vector<std::uint8_t> png, std::string detail) {
  ChatPart p;
  p.kind = Kind::PngImage;
  p.png = std::move(png);
  p.detail = std::move(detail);
  return p;
}

std::string png_data_url(const std::vector<std::uint8_t>& png) {
  return "data:image/png;base64," + base64_encode(std::span<const std::uint8_t>(png));
}

std::string parse_chat_reply(const std::string& body, const ChatRequest& request,
                             const std::string& context) {
  const json j = parse_choices_reply(body, context);
  const auto choices = j.find("choices");
  if (choices->empty()) throw LmError(context + "choices is empty");
  const json& choice = (*choices)[0];
  if (!choice.is_object()) throw LmError(context + "choices[0] is not an object");
  auto message = choice.find("message");
  if (message == choice.end() || !message->is_object()) {
    throw LmError(context + "choices[0].message missing");
  }
  auto content = message->find("content");
  if (content == message->end() || content->is_null()) {
    std::string why;
    if (auto r = message->find("refusal"); r != message->end() && r->is_string()) {
      why = " (refusal: " + r->get<std::string>() + ")";
    }
    throw LmError(context + "choices[0].message.content missing" + why);
  }
  if (!content->is_string()) throw LmError(context + "choices[0].message.content is not a string");
  std::string text = content->get<std::string>();

  if (request.json_object && request.validate_json &&
      json::parse(text, nullptr, /*allow_exceptions=*/false).is_discarded()) {
    std::string finish;
    if (auto f = choice.find("finish_reason"); f != choice.end() && f->is_string()) {
      finish = ", finish_reason " + f->get<std::string>();
    }
    throw LmError(context + "choices[0].message.content is not valid JSON although a JSON object was "
                  "requested (" + std::to_string(text.size()) + " chars" + finish + ")");
  }
  return text;
}

OpenAiChatClient::OpenAiChatClient(OpenAiChatOptions options) : http_(options.http) {
  std::string base = options.base_url.empty()
                         ? env_or("CLIPS_CHAT_BASE_URL", "https://api.openai.com/v1")
                         : options.base_url;
  if (const std::string why = base_url_problem(base); !why.empty())
    throw LmError("base URL " + why + (options.base_url.empty() ? " ($CLIPS_CHAT_BASE_URL)" : ""));
  endpoint_ = join_url(base, "/chat/completions");
  model_ = options.model.empty() ? env_or("CLIPS_CHAT_MODEL", "gpt-4o") : options.model;
  api_key_ = options.api_key ? *options.api_key : env_or("OPENAI_API_KEY", "");
}

std::string OpenAiChatClient::request_body(const ChatRequest& request) const {
  json messages = json::array();
  for (const auto& m : request.messages) {
    json content = json::array();
    for (const auto& part : m.parts) {
      if (part.kind == ChatPart::Kind::Text) {
        content.push_back({{"type", "text"}, {"text", part.text}});
      } else {
        json image = {{"url", png_data_url(part.png)}};
        if (!part.detail.empty()) image["detail"] = part.detail;
        content.push_back({{"type", "image_url"}, {"image_url", image}});
      }
    }
    messages.push_back({{"role", m.role}, {"content", content}});
  }
  json body = {{"model", model_}, {"messages", messages}};
  if (request.temperature) body["temperature"] = *request.temperature;
  if (request.max_tokens) body["max_tokens"] = *request.max_tokens;
  if (request.json_object) body["response_format"] = {{"type", "json_object"}};
  return body.dump();
}

std::string OpenAiChatClient::complete(const ChatRequest& request) {
  std::vector<std::string> headers;
  if (!api_key_.empty()) headers.push_back("Authorization: Bearer " + api_key_);
  HttpResponse reply = http_.post_json(endpoint_, request_body(request), headers);
  if (reply.status < 200 || reply.status >= 300) {
    throw LmError("POST " + endpoint_ + ": HTTP " + std::to_string(reply.status) + ": " +
                  server_error_text(reply.body));
  }

  return parse_chat_reply(reply.body, request, "reply from " + endpoint_ + ": ");
}

}  // namespace clips::lm
