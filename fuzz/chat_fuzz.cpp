// The OpenAI-compatible /v1/chat/completions reply parser. The first byte's
// low bit asks for a JSON-object answer (checked to parse); the rest is the body.
#include "fuzz/fuzz_target.hpp"
#include "lm/openai_chat.hpp"

CLIPS_FUZZ_TARGET(chat) {
  using namespace clips::lm;
  if (size == 0) return 0;
  ChatRequest request;
  request.json_object = (data[0] & 1) != 0;
  try {
    (void)parse_chat_reply(clips::fuzz::as_text(data + 1, size - 1), request, "<reply>: ");
  } catch (const LmError&) {
  }
  return 0;
}
