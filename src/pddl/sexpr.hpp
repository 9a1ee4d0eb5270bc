#pragma once
// S-expression reader for PDDL text. Symbols are lower-cased (PDDL is
// case-insensitive); `;` starts a comment that runs to the end of the line.
// Every node remembers where it started so later stages can report
// file:line:col in their errors.
#include <string>
#include <vector>

#include "util/error.hpp"

namespace clips::pddl {

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
// Parses exactly one expression (e.g. a goal given on the command line).
SExpr read_one_sexpr(const std::string& text, const std::string& label);
std::string read_text_file(const std::string& path);

}  // namespace clips::pddl
