#pragma once
// Errors raised on bad input. Every message names where the problem is
// (file:line:col for text inputs, a field path for JSON) and what was expected,
// so the CLI can print it as is and exit non-zero.
#include <stdexcept>
#include <string>

namespace clips {

struct SourceLoc {
  std::string file;  // path or a label such as "<goal>"
  int line = 0;      // 1-based; 0 = unknown
  int col = 0;       // 1-based; 0 = unknown
  std::string str() const;
};

class InputError : public std::runtime_error {
 public:
  InputError(const SourceLoc& loc, const std::string& what);
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

// A budget stopped the work before it finished: a wall-clock limit, or memory
// that would run out (refused before it did). Not a fault in the input.
class LimitError : public std::runtime_error {
 public:
  enum class Kind { Time, Memory };
  LimitError(Kind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  Kind kind() const noexcept { return kind_; }

 private:
  Kind kind_;
};

}  // namespace clips
