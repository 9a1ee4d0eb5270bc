#pragma once
// Client for OpenAI-compatible /v1/chat/completions with text and PNG image
// parts, used by the multimodal baseline. Same transport, retries and error
// style as the completions backend.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lm/http_client.hpp"
#include "lm/language_model.hpp"

namespace clips::lm {

struct ChatPart {
  enum class Kind { Text, PngImage };
  Kind kind = Kind::Text;
  std::string text;               // Kind::Text
  std::vector<std::uint8_t> png;  // Kind::PngImage: raw PNG file bytes
  std::string detail;             // image detail hint ("low"/"high"/"auto"); "" = omit

  static ChatPart from_text(std::string text);
  static ChatPart from_png(std::vector<std::uint8_t> png, std::string detail = "");
};

struct ChatMessage {
  std::string role;  // "system", "user" or "assistant"
  std::vector<ChatPart> parts;
};

struct ChatRequest {
  std::vector<ChatMessage> messages;
  std::optional<double> temperature;
  std::optional<int> max_tokens;
  bool json_object = false;  // send response_format {"type":"json_object"}
  // With json_object: throw LmError if the answer does not parse as JSON.
  bool validate_json = true;
};

struct OpenAiChatOptions {
  std::string base_url;                // "" -> $CLIPS_CHAT_BASE_URL, else https://api.openai.com/v1
  std::string model;                   // "" -> $CLIPS_CHAT_MODEL, else gpt-4o
  std::optional<std::string> api_key;  // nullopt -> $OPENAI_API_KEY; "" -> no Authorization header
  HttpOptions http;
};

class OpenAiChatClient {
 public:
  explicit OpenAiChatClient(OpenAiChatOptions options = {});

  // The assistant message text of the first choice.
  std::string complete(const ChatRequest& request);

  // The JSON body complete() would send (exposed for tests and logging).
  std::string request_body(const ChatRequest& request) const;

  const std::string& endpoint() const { return endpoint_; }
  const std::string& model() const { return model_; }

 private:
  std::string endpoint_;
  std::string model_;
  std::string api_key_;
  HttpClient http_;
};

// The assistant message text of the first choice in a /v1/chat/completions
// reply `body`; with request.json_object and validate_json it must parse as
// JSON. Throws LmError, prefixed by `context`, on anything else.
std::string parse_chat_reply(const std::string& body, const ChatRequest& request,
                             const std::string& context);

// "data:image/png;base64,<...>"
std::string png_data_url(const std::vector<std::uint8_t>& png);

}  // namespace clips::lm
