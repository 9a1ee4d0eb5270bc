#include "domains/dkg/dkg_goals.hpp"

#include <map>
#include <set>

#include "pddl/sexpr.hpp"

namespace clips::domains::dkg {

namespace {

struct Atoms {
  std::map<std::string, std::set<std::string>> holders;     // item -> agents that must hold it
  std::map<std::string, std::set<std::string>> door_keys;   // door -> keys that must have opened it
  std::map<std::string, std::set<std::string>> key_doors;   // key -> doors it must have opened
  std::set<std::pair<std::string, std::string>> distinct;   // (not (= a b)) between variables
};

// Collects atoms of a conjunction; returns false if the formula has a
// disjunction or quantifier other than exists above its atoms (then no
// conclusion is drawn).
bool collect(const pddl::SExpr& e, Atoms& a) {
  if (!e.is_list || e.items.empty()) return true;
  const std::string& h = e.head();
  if (h == "and") {
    for (size_t i = 1; i < e.items.size(); ++i)
      if (!collect(e.items[i], a)) return false;
    return true;
  }
  if (h == "exists") return e.items.size() == 3 && collect(e.items[2], a);
  if (h == "not") {
    const pddl::SExpr& in = e.items.size() == 2 ? e.items[1] : e;
    if (in.is_list && in.head() == "=" && in.items.size() == 3) {
      a.distinct.insert({in.items[1].str(), in.items[2].str()});
      a.distinct.insert({in.items[2].str(), in.items[1].str()});
    }
    return true;
  }
  if (h == "or" || h == "imply" || h == "forall") return false;
  if (h == "has" && e.items.size() == 3) a.holders[e.items[2].str()].insert(e.items[1].str());
  if (h == "unlocked-with" && e.items.size() == 3) {
    a.door_keys[e.items[2].str()].insert(e.items[1].str());
    a.key_doors[e.items[1].str()].insert(e.items[2].str());
  }
  return true;
}

// Two terms surely name different objects: two different constants, or two
// variables the formula declares unequal.
bool surely_distinct(const std::string& x, const std::string& y, const Atoms& a) {
  if (x == y) return false;
  bool vx = !x.empty() && x[0] == '?', vy = !y.empty() && y[0] == '?';
  if (!vx && !vy) return true;
  return a.distinct.count({x, y}) > 0;
}

bool two_distinct(const std::set<std::string>& s, const Atoms& a) {
  for (auto i = s.begin(); i != s.end(); ++i)
    for (auto j = std::next(i); j != s.end(); ++j)
      if (surely_distinct(*i, *j, a)) return true;
  return false;
}

}  // namespace

bool dkg_goal_unsatisfiable(const std::string& goal) {
  pddl::SExpr e;
  try {
    e = pddl::read_one_sexpr(goal, "<goal>");
  } catch (...) {
    return false;
  }
  Atoms a;
  if (!collect(e, a)) return false;
  // A used key is off the grid and held by nobody, forever.
  for (auto& [key, doors] : a.key_doors)
    if (a.holders.count(key)) return true;
  // Only one agent holds an item at a time; hand-overs move it.
  for (auto& [item, agents] : a.holders)
    if (two_distinct(agents, a)) return true;
  // A door is unlocked once, by one key; a key opens one door (it is consumed).
  for (auto& [door, keys] : a.door_keys)
    if (two_distinct(keys, a)) return true;
  for (auto& [key, doors] : a.key_doors)
    if (two_distinct(doors, a)) return true;
  return false;
}

}  // namespace clips::domains::dkg
