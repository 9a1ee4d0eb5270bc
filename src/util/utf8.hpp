#pragma once
// UTF-8 well-formedness, shared by the file loaders and the command line so
// that an utterance is checked the same way wherever it comes from.
#include <string>

namespace clips::util {

// Index of the first byte of `s` that is not part of well-formed UTF-8
// (overlong forms, surrogates and code points above U+10FFFF are rejected),
// or std::string::npos when all of it is well-formed.
size_t invalid_utf8_at(const std::string& s);

// "" when `s` is well-formed UTF-8, else a description such as
// "not valid UTF-8 (byte 0xff at offset 3)".
std::string utf8_problem(const std::string& s);

}  // namespace clips::util
