#include "util/error.hpp"

namespace clips {

std::string SourceLoc::str() const {
  std::string s = file.empty() ? "<input>" : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (col > 0) s += ":" + std::to_string(col);
  }
  return s;
}

namespace {
bool continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
}  // namespace

std::string clip_message(const std::string& text, size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  size_t head = max_bytes * 3 / 4, tail = text.size() - max_bytes / 4;
  while (head > 0 && continuation_byte(text[head])) --head;
  while (tail < text.size() && continuation_byte(text[tail])) ++tail;
  return text.substr(0, head) + "... (" + std::to_string(text.size()) + " bytes in all) ..." + text.substr(tail);
}

InputError::InputError(const SourceLoc& loc, const std::string& what)
    : std::runtime_error(clip_message(loc.str() + ": " + what)) {}

}  // namespace clips
