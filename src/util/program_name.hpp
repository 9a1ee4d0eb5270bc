#pragma once
// The name the command was run as, for messages, --help and --version: the
// build tree's binary is `clips`, the installed one `clips-assist` (Debian's
// /usr/bin/clips is the CLIPS expert system). Set once by main() from argv[0],
// before any thread starts.
#include <string>

namespace clips::util {

// "clips" until set_program_name() says otherwise.
const std::string& program_name();
// The last path component of `argv0`; an empty or missing one keeps "clips".
void set_program_name(const char* argv0);

}  // namespace clips::util
