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

// A call stopped before it was done: by its wall-clock limit (CallLimits,
// `--max-seconds`/`--time-limit`, grounding included) or its cancellation.
class CallStoppedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
class TimeLimitError : public CallStoppedError {
 public:
  using CallStoppedError::CallStoppedError;
};
class CancelledError : public CallStoppedError {
 public:
  using CallStoppedError::CallStoppedError;
};

// Work refused because memory would run out (grounding a task too large for
// what the process has left), before it did.
class MemoryLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace clips
