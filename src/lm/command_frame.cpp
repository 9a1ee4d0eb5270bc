#include "lm/command_frame.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>

#include "lm/language_model.hpp"

namespace clips::lm {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string strip_var(std::string_view s) {
  while (!s.empty() && s.front() == '?') s.remove_prefix(1);
  return lower(s);
}

bool is_pronoun(std::string_view s) { return s == "you" || s == "me"; }

// An attribute value as a word: lower case, no trailing digits, the last
// part of a compound name ("fridge1" -> "fridge", "veg-patch" -> "patch").
std::string value_word(std::string_view v) {
  std::string w = lower(v);
  while (w.size() > 1 && std::isdigit(static_cast<unsigned char>(w.back()))) w.pop_back();
  const size_t cut = w.find_last_of("-_");
  if (cut != std::string::npos && cut + 1 < w.size()) w = w.substr(cut + 1);
  return w;
}

using Term = std::vector<std::string>;

[[noreturn]] void fail(std::string_view what_for, std::string_view command, const std::string& why) {
  throw LmError("embedded LM: cannot parse command \"" + std::string(command) + "\" (" +
                std::string(what_for) + "): " + why);
}

}  // namespace

std::string variable_type(std::string_view name) {
  std::string s = strip_var(name);
  while (!s.empty() && std::isdigit(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

CommandFrame parse_command_frame(std::string_view command, std::string_view what_for) {
  std::vector<Term> actions;
  std::vector<Term> predicates;
  bool in_where = false;
  size_t i = 0;
  const size_t n = command.size();
  while (i < n) {
    const char c = command[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '(') {
      const size_t close = command.find(')', i);
      if (close == std::string_view::npos) fail(what_for, command, "missing ')'");
      Term term;
      std::string_view body = command.substr(i + 1, close - i - 1);
      size_t k = 0;
      while (k < body.size()) {
        while (k < body.size() && std::isspace(static_cast<unsigned char>(body[k]))) ++k;
        size_t start = k;
        while (k < body.size() && !std::isspace(static_cast<unsigned char>(body[k]))) ++k;
        if (k > start) term.push_back(strip_var(body.substr(start, k - start)));
      }
      if (term.empty()) fail(what_for, command, "empty term");
      if (term[0].find('(') != std::string::npos) fail(what_for, command, "nested term");
      (in_where ? predicates : actions).push_back(std::move(term));
      i = close + 1;
      continue;
    }
    size_t start = i;
    while (i < n && !std::isspace(static_cast<unsigned char>(command[i])) && command[i] != '(') ++i;
    const std::string word = lower(command.substr(start, i - start));
    if (word == "where" && !in_where) {
      in_where = true;
    } else {
      fail(what_for, command, "unexpected text '" + word + "'");
    }
  }

  // Variable types and attributes from the predicates. A value that is an
  // object's name (a place: "fridge1", "veg-patch") is read as the word
  // people say: no trailing digits, the last part of a compound ("patch").
  std::map<std::string, std::string> type_override;
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> attributes;  // value, predicate
  std::map<std::string, std::vector<std::string>> numbers;
  for (const Term& p : predicates) {
    if (p.size() != 3) continue;  // only (pred var value) carries lexical content
    if (p[0] == "itemtype" || p[0] == "type") {
      type_override[p[1]] = lower(p[2]);
    } else if (const size_t hash = p[2].find('#'); hash != std::string::npos && hash > 0 && hash + 1 < p[2].size()) {
      attributes[p[1]].emplace_back(value_word(p[2].substr(0, hash)), p[0]);
      numbers[p[1]].push_back(p[2].substr(hash + 1));
    } else {
      attributes[p[1]].emplace_back(value_word(p[2]), p[0]);
    }
  }

  CommandFrame frame;
  frame.num_actions = static_cast<int>(actions.size());
  for (const Term& a : actions) {
    std::string agent = "you";
    size_t first_arg = 1;
    if (a.size() > 1 && is_pronoun(a[1])) {
      agent = a[1];
      first_arg = 2;
    }
    bool to_speaker = false;
    std::string focal;
    for (size_t k = first_arg; k < a.size(); ++k) {
      if (a[k] == "me") to_speaker = true;
      if (!is_pronoun(a[k])) focal = a[k];
    }
    if (agent == "me") to_speaker = false;
    std::string type, focal_number;
    if (!focal.empty()) {
      auto it = type_override.find(focal);
      // A named place said with its number ("(open you door#2)").
      const size_t hash = focal.find('#');
      if (it == type_override.end() && hash != std::string::npos && hash > 0 && hash + 1 < focal.size())
        focal_number = focal.substr(hash + 1);
      type = it != type_override.end() ? it->second : variable_type(focal.substr(0, hash));
    }
    auto g = std::find_if(frame.groups.begin(), frame.groups.end(), [&](const FrameGroup& x) {
      return x.agent == agent && x.action == a[0] && x.type == type && x.to_speaker == to_speaker;
    });
    if (g == frame.groups.end()) {
      frame.groups.push_back(FrameGroup{agent, a[0], to_speaker, type, 0, {}, {}, {}});
      g = frame.groups.end() - 1;
    }
    ++g->count;
    if (!focal_number.empty() && std::find(g->numbers.begin(), g->numbers.end(), focal_number) == g->numbers.end())
      g->numbers.push_back(focal_number);
    if (!focal.empty()) {
      if (auto nt = numbers.find(focal); nt != numbers.end())
        for (const std::string& v : nt->second)
          if (std::find(g->numbers.begin(), g->numbers.end(), v) == g->numbers.end()) g->numbers.push_back(v);
      auto at = attributes.find(focal);
      if (at != attributes.end()) {
        for (const auto& [v, predicate] : at->second) {
          if (std::find(g->attributes.begin(), g->attributes.end(), v) == g->attributes.end()) {
            g->attributes.push_back(v);
            g->attribute_predicates.push_back(predicate);
          }
        }
      }
    }
  }
  return frame;
}

}  // namespace clips::lm
