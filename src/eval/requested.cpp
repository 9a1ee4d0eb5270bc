#include "eval/requested.hpp"

#include <algorithm>
#include <cctype>

#include "util/error.hpp"

namespace clips::eval {

namespace {

// The words and parentheses of `text`.
std::vector<std::string> tokens(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) out.push_back(std::move(word));
    word.clear();
  };
  for (char c : text) {
    if (c == '(' || c == ')') {
      flush();
      out.emplace_back(1, c);
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      flush();
    } else {
      word.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  flush();
  return out;
}

}  // namespace

std::string requested_where(const data::Dataset& ds, const data::PlanRecord& p) {
  return ds.dir() + "/instructions.tsv, plan " + p.id;
}

std::vector<RequestedAtom> parse_requested(const pddl::Task& task, const std::string& text, const std::string& where) {
  const std::vector<std::string> t = tokens(text);
  std::vector<RequestedAtom> out;
  size_t i = 0;
  auto fail = [&](const std::string& why) { throw InputError(where + ": requested '" + text + "': " + why); };
  // One "(pred obj ...)" from t[i]; returns its words.
  auto atom = [&]() {
    if (i >= t.size() || t[i] != "(") fail("expected '(' to start an atom");
    ++i;
    std::vector<std::string> words;
    while (i < t.size() && t[i] != ")") {
      if (t[i] == "(") fail("an atom's arguments are object names, not atoms");
      words.push_back(t[i++]);
    }
    if (i >= t.size()) fail("an atom is not closed with ')'");
    ++i;
    if (words.empty()) fail("an empty atom '()'");
    return words;
  };
  while (i < t.size()) {
    bool positive = true;
    std::vector<std::string> words;
    if (i + 2 < t.size() && t[i] == "(" && t[i + 1] == "not" && t[i + 2] == "(") {
      ++i;  // "("
      ++i;  // "not"
      words = atom();
      if (i >= t.size() || t[i] != ")") fail("(not ...) holds one atom and is closed with ')'");
      ++i;
      positive = false;
    } else {
      words = atom();
    }
    const std::string printed = "(" + words.front() + [&] {
      std::string rest;
      for (size_t k = 1; k < words.size(); ++k) rest += " " + words[k];
      return rest;
    }() + ")";
    pddl::Task::AtomRef ref;
    try {
      ref = task.atom(words.front(), std::vector<std::string>(words.begin() + 1, words.end()));
    } catch (const InputError& e) {
      fail(printed + ": " + e.what());
    }
    if (ref.bit < 0)
      fail(printed + " never changes in this problem (it is " + (ref.value ? "always true" : "always false") +
           "), so no action can bring it about");
    out.push_back({ref.bit, positive});
  }
  if (out.empty()) fail("no atom");
  return out;
}

std::optional<bool> request_done(const pddl::Task& task, const pddl::State& start, pddl::ObjectId assistant,
                                 const std::vector<RequestedAtom>& atoms, const std::vector<pddl::ActionId>& actions) {
  if (atoms.empty()) return std::nullopt;
  std::vector<char> done(atoms.size(), 0);
  pddl::State s = start;
  for (pddl::ActionId a : actions) {
    if (!task.applicable(a, s.data())) break;
    const pddl::GroundAction& ga = task.action(a);
    pddl::State next = task.apply(s, a);
    if (!ga.args.empty() && ga.args.front() == assistant)
      for (size_t k = 0; k < atoms.size(); ++k) {
        const bool before = pddl::get_bit(s.data(), atoms[k].bit), after = pddl::get_bit(next.data(), atoms[k].bit);
        if (before != atoms[k].positive && after == atoms[k].positive) done[k] = 1;
      }
    s = std::move(next);
  }
  return std::all_of(done.begin(), done.end(), [](char d) { return d != 0; });
}

}  // namespace clips::eval
