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

// A message of at most about `max_bytes`: a longer one keeps its start and its
// end, cut at UTF-8 character boundaries, with "... (N bytes) ..." between, so
// that a huge value echoed into an error (a 1 MB pack field) stays readable.
std::string clip_message(const std::string& text, size_t max_bytes = 2000);

// Its message is clipped (clip_message): it may quote input of any size.
class InputError : public std::runtime_error {
 public:
  InputError(const SourceLoc& loc, const std::string& what);
  explicit InputError(const std::string& what) : std::runtime_error(clip_message(what)) {}
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
