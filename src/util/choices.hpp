#pragma once
// One table per kind of named choice (a method, an assistance rule, a
// modality, a heuristic, ...): each value registered once, with its name, a
// line of help and the older spellings still read (docs/decisions.md, "One
// registry of named choices"). The table is defined beside the kind's enum;
// the CLI's flags (their help and accepted values), Python's keywords and the
// server's fields and OpenAPI enums are built from it, so a name exists once.
//
// Text is parsed at the edge (parse), and a bad name's error lists the valid
// ones: "unknown assistance rule 'x' (known: qmdp, pibar)".
//
// A table takes entries at run time too (add): a front end built afterwards
// lists them. Register at start-up, before any reader runs: the table is not
// locked (readers are many threads, writers a program's or test's set-up).
#include <deque>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/error.hpp"

namespace clips::util {

template <typename V>
struct Choice {
  V value{};
  std::string name;                  // canonical: written back, listed first
  std::string help;                  // one line: what it does
  std::vector<std::string> aliases;  // older spellings, still read
};

// A table's names and help without its value type: for catalogues (Python's
// choices(), the docs' table, the server's schema check).
struct ChoiceInfo {
  std::string name, help;
  std::vector<std::string> aliases;
};
struct ChoiceKind {
  std::string kind;  // as errors say it: "assistance rule"
  std::vector<ChoiceInfo> choices;
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& c : choices) out.push_back(c.name);
    return out;
  }
  // Names and aliases: what a field that reads older spellings takes.
  std::vector<std::string> spellings() const {
    std::vector<std::string> out;
    for (const auto& c : choices) {
      out.push_back(c.name);
      out.insert(out.end(), c.aliases.begin(), c.aliases.end());
    }
    return out;
  }
};
// Every kind a front end offers, by the field, keyword or flag name it goes
// by ("assistance", "rejuvenate"): the catalogue Python, the docs and the
// server's schema are checked against.
using ChoiceCatalogue = std::vector<std::pair<std::string, ChoiceKind>>;

// "a, b or c".
inline std::string or_list(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

template <typename V>
class Choices {
 public:
  Choices(std::string kind, std::initializer_list<Choice<V>> entries) : kind_(std::move(kind)) {
    for (const auto& e : entries) add(e);
  }

  const std::string& kind() const { return kind_; }

  // Registers one more value; a name or alias already taken is a bug.
  void add(Choice<V> c) {
    if (c.name.empty()) throw std::logic_error(kind_ + ": a choice needs a name");
    for (const std::string& n : spellings(c))
      if (find(n)) throw std::logic_error(kind_ + " '" + n + "' registered twice");
    entries_.push_back(std::move(c));
  }

  // Takes a registered value back out (a test's own registration).
  void remove(const std::string& name) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->name == name) {
        entries_.erase(it);
        return;
      }
  }

  const std::deque<Choice<V>>& entries() const { return entries_; }

  // Canonical names, in registration order.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e.name);
    return out;
  }
  // Canonical names and aliases: every spelling parse reads.
  std::vector<std::string> spellings() const {
    std::vector<std::string> out;
    for (const auto& e : entries_)
      for (const std::string& n : spellings(e)) out.push_back(n);
    return out;
  }

  bool contains(const std::string& text) const { return find(text) != nullptr; }

  // The value of a name or alias; InputError naming the kind and listing the names.
  V parse(const std::string& text) const {
    if (const Choice<V>* c = find(text)) return c->value;
    throw InputError(unknown(text));
  }
  // "unknown assistance rule 'x' (known: qmdp, pibar; also read: ...)".
  std::string unknown(const std::string& text) const {
    std::string known, aliases;
    for (const auto& e : entries_) {
      known += (known.empty() ? "" : ", ") + e.name;
      for (const std::string& a : e.aliases) aliases += (aliases.empty() ? "" : ", ") + a;
    }
    return "unknown " + kind_ + " '" + text + "' (known: " + known +
           (aliases.empty() ? "" : "; also read: " + aliases) + ")";
  }

  // The canonical name of a value (needs V ==).
  const std::string& name(const V& v) const { return of(v).name; }
  const std::string& help(const V& v) const { return of(v).help; }

  // "a (what a does), b (what b does) or c (...)": for help texts.
  std::string help_text() const {
    std::vector<std::string> parts;
    for (const auto& e : entries_) parts.push_back(e.help.empty() ? e.name : e.name + " (" + e.help + ")");
    return or_list(parts);
  }
  // "a, b or c".
  std::string name_list() const { return or_list(names()); }

  ChoiceKind info() const {
    ChoiceKind k{kind_, {}};
    for (const auto& e : entries_) k.choices.push_back({e.name, e.help, e.aliases});
    return k;
  }

 private:
  static std::vector<std::string> spellings(const Choice<V>& c) {
    std::vector<std::string> s{c.name};
    s.insert(s.end(), c.aliases.begin(), c.aliases.end());
    return s;
  }
  const Choice<V>* find(const std::string& text) const {
    for (const auto& e : entries_)
      for (const std::string& n : spellings(e))
        if (n == text) return &e;
    return nullptr;
  }
  const Choice<V>& of(const V& v) const {
    for (const auto& e : entries_)
      if (e.value == v) return e;
    throw std::logic_error(kind_ + ": a value with no name");
  }

  std::string kind_;
  std::deque<Choice<V>> entries_;  // a deque: references stay valid as entries are added
};

}  // namespace clips::util
