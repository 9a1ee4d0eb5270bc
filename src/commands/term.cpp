#include "commands/term.hpp"

#include <cctype>
#include <stdexcept>

namespace clips::commands {

std::string to_pddl(const Term& term) {
  std::string out = "(" + term.name;
  for (const auto& arg : term.args) out += " " + arg;
  return out + ")";
}

std::string to_pddl(const std::vector<Term>& terms) {
  std::string out;
  for (const auto& term : terms) {
    if (!out.empty()) out += ' ';
    out += to_pddl(term);
  }
  return out;
}

namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

[[noreturn]] void fail(std::string_view text, const std::string& why) {
  throw std::invalid_argument("bad PDDL term '" + std::string(text) + "': " + why);
}

// Parses the term starting at text[pos] == '(' and advances pos past ')'.
Term parse_at(std::string_view text, std::size_t& pos) {
  ++pos;  // '('
  std::vector<std::string> tokens;
  while (true) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos >= text.size()) fail(text, "missing ')'");
    const char c = text[pos];
    if (c == ')') {
      ++pos;
      break;
    }
    if (c == '(') fail(text, "nested terms are not supported");
    const std::size_t start = pos;
    while (pos < text.size() && !is_space(text[pos]) && text[pos] != '(' && text[pos] != ')') ++pos;
    tokens.emplace_back(text.substr(start, pos - start));
  }
  if (tokens.empty()) fail(text, "empty term");
  Term term{tokens.front(), {}};
  term.args.assign(tokens.begin() + 1, tokens.end());
  return term;
}

}  // namespace

std::vector<Term> parse_terms(std::string_view text) {
  std::vector<Term> terms;
  std::size_t pos = 0;
  while (true) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos >= text.size()) break;
    if (text[pos] != '(') fail(text, "expected '(' at offset " + std::to_string(pos));
    terms.push_back(parse_at(text, pos));
  }
  return terms;
}

Term parse_term(std::string_view text) {
  auto terms = parse_terms(text);
  if (terms.size() != 1) fail(text, "expected exactly one term, found " + std::to_string(terms.size()));
  return std::move(terms.front());
}

}  // namespace clips::commands
