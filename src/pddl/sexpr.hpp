#pragma once
// S-expression reader for PDDL text. Symbols are lower-cased (PDDL is
// case-insensitive); `;` starts a comment that runs to the end of the line;
// `?` starts a new symbol (a variable), also right after a name: `(at?x)`.
// Every node remembers where it started so later stages can report
// file:line:col in their errors. A leading UTF-8 byte-order mark is skipped.
#include <string>
#include <vector>

#include "util/error.hpp"

namespace clips::pddl {

// Lists nest at most this deep: real PDDL stays below 10 levels, and every
// recursive pass over expressions (reading, conversion, grounding) relies on
// this bound to stay far from a stack overflow.
constexpr int kMaxNesting = 1000;
// At most this many atoms and lists in one text: the largest dataset file has
// under 2,000, and each node costs ~100 bytes, so a huge input (50 MB of
// repeated tokens) is refused in a fraction of a second instead of after
// gigabytes.
constexpr long kMaxTokens = 1'000'000;

// An error of the reader itself; keeps location and message apart so callers
// can add context without repeating the location.
class SyntaxError : public InputError {
 public:
  SyntaxError(const SourceLoc& loc, const std::string& message)
      : InputError(loc, message), loc(loc), message(message) {}
  SourceLoc loc;
  std::string message;
};

struct SExpr {
  bool is_list = false;
  std::string atom;           // lower-cased symbol, when !is_list
  std::vector<SExpr> items;   // children, when is_list
  SourceLoc loc;

  bool is_atom() const { return !is_list; }
  bool is_atom(const std::string& s) const { return !is_list && atom == s; }
  // The head symbol of a list, or "" if it is empty or starts with a list.
  const std::string& head() const;
  std::string str() const;  // back to text (single line)
};

// Parses every top-level expression of `text`; `file` is used in messages.
std::vector<SExpr> read_sexprs(const std::string& text, const std::string& file);
// A PDDL file: one top-level list. A top-level atom or any text after the
// first expression is an error at once, before the rest is read.
std::vector<SExpr> read_pddl_forms(const std::string& text, const std::string& file);
// Parses exactly one expression (e.g. a goal given on the command line).
SExpr read_one_sexpr(const std::string& text, const std::string& label);
// The same for text cut out of a file at `origin`, so positions point into it.
SExpr read_one_sexpr(const std::string& text, const SourceLoc& origin);
std::string read_text_file(const std::string& path);

// Input text made safe to quote in an error message: control bytes (other than
// tab) are written as \xHH so they cannot act on the terminal, and text longer
// than `max_len` bytes is cut short with "...".
std::string printable(const std::string& text, size_t max_len = std::string::npos);

}  // namespace clips::pddl
