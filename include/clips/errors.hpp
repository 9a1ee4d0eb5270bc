#pragma once
// The exceptions clips throws. All derive from std::runtime_error, and every
// message names the offending input (file:line:col for text files, a JSON
// field, the action or utterance given), so it can be shown to a user as is.
//
//   clips::InputError               bad input: malformed PDDL or plan, unknown
//                                   object or action, unknown option value,
//                                   missing file or data directory
//   clips::InapplicableActionError  a well-formed action whose precondition is
//                                   false in the current state (an InputError)
//   clips::LanguageModelError       the language model failed (unreachable
//                                   server, malformed reply)
//   clips::TimeLimitError           a wall-clock limit passed (CallLimits);
//                                   the session is as before the call
//   clips::CancelledError           a call was cancelled (CallLimits); the
//                                   session is as before the call
//   clips::MemoryLimitError         refused before memory ran out (e.g. a
//                                   problem too large to ground here)
#include <stdexcept>
#include <string>

#ifdef CLIPS_BUILDING_LIBRARY
// Inside the library, InputError is the internals' own (util/error.hpp),
// which every stage throws.
#include "util/error.hpp"
#else
namespace clips {

// The same definitions as src/util/error.hpp (token for token: one type,
// defined in two headers; the library's own code sees that one).
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
#endif

namespace clips {

class InapplicableActionError : public InputError {
 public:
  InapplicableActionError(std::string action, const std::string& what)
      : InputError(what), action_(std::move(action)) {}
  // The action as it was given.
  const std::string& action() const noexcept { return action_; }

 private:
  std::string action_;
};

class LanguageModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace clips
