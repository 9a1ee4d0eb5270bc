#pragma once
// A flat PDDL term such as `(pickup robot key2)` or `(iscolor ?key1 red)`.
// Commands only ever need flat terms: an action or predicate name applied to
// constants, pronouns (`me`, `you`) or variables (arguments starting with '?').
#include <string>
#include <string_view>
#include <vector>

namespace clips::commands {

struct Term {
  std::string name;
  std::vector<std::string> args;

  bool operator==(const Term&) const = default;
  auto operator<=>(const Term&) const = default;
};

// True for a variable argument such as "?key1".
inline bool is_variable(std::string_view arg) { return !arg.empty() && arg.front() == '?'; }

// "(name a b)"; a term without arguments prints as "(name)".
std::string to_pddl(const Term& term);
// Terms joined by single spaces.
std::string to_pddl(const std::vector<Term>& terms);

// Parses one flat term, e.g. "(handover robot human key1)". Names are kept as
// written (no case folding). Throws std::invalid_argument naming the text.
Term parse_term(std::string_view text);
// Parses a whitespace-separated sequence of flat terms, e.g. "(a x) (b y)".
std::vector<Term> parse_terms(std::string_view text);

}  // namespace clips::commands
