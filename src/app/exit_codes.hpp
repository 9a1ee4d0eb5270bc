#pragma once
// Exit statuses of `clips`, one per kind of outcome, so that scripts can tell
// a typo from bad data, "no plan exists" from "ran out of budget", and a
// failing language-model server from a bug. docs/cli.md has the table; the
// --help footer repeats it. Modelled on how Fast Downward documents its own
// statuses: the low numbers are results, the rest name what stopped the run.
#include <stdexcept>
#include <string>

namespace clips::app {

enum ExitCode : int {
  kExitOk = 0,             // the command did what was asked
  kExitSomeFailed = 1,     // it ran to the end, but some items failed (validate, bench: see its report)
  kExitUsage = 2,          // bad command line: unknown option or subcommand, missing or malformed value
  kExitInput = 3,          // bad input data: unreadable file, malformed PDDL/plan/JSON, unknown object, ...
  kExitUnsolvable = 4,     // search finished and proved that no plan reaches the goal
  kExitLimit = 5,          // a time, node or step limit stopped the search before it found a plan
  kExitLanguageModel = 6,  // the language model or chat server failed (network, HTTP, malformed reply, cannot score)
  kExitOutOfMemory = 7,    // memory ran out
  kExitInternal = 8,       // an unexpected internal error (a bug: please report it)
  kExitCannotListen = 9,   // serve: the port is in use (or the address cannot be bound)
};

// The table printed at the end of `clips --help`.
std::string exit_code_help();

// A usage mistake found after parsing (e.g. an option that depends on another
// one): exits with kExitUsage like CLI11's own parse errors.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace clips::app
