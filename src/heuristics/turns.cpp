#include "heuristics/turns.hpp"

#include "heuristics/conditions.hpp"

#include <algorithm>

namespace clips::heuristics {

namespace {

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

TurnStructure TurnStructure::of(const pddl::Task& task) {
  TurnStructure ts;
  const int na = task.num_actions();
  if (na == 0) return ts;
  ts.agent_of.assign(static_cast<size_t>(na), -1);
  // Candidate turn atoms per agent: required and deleted by all its actions.
  std::vector<std::vector<int>> cand;
  std::vector<bool> seen;
  for (pddl::ActionId a = 0; a < na; ++a) {
    const auto& ga = task.action(a);
    if (ga.args.empty()) return ts;
    auto it = std::find(ts.agents.begin(), ts.agents.end(), ga.args[0]);
    const int x = static_cast<int>(it - ts.agents.begin());
    if (it == ts.agents.end()) {
      ts.agents.push_back(ga.args[0]);
      cand.emplace_back();
      seen.push_back(false);
    }
    ts.agent_of[static_cast<size_t>(a)] = x;
    std::vector<int> pre;
    conjuncts(task, ga.pre, pre);
    pre = sorted(pre);
    const std::vector<int> del = sorted(ga.eff.del);
    std::vector<int> both;
    std::set_intersection(pre.begin(), pre.end(), del.begin(), del.end(), std::back_inserter(both));
    if (!seen[static_cast<size_t>(x)]) {
      cand[static_cast<size_t>(x)] = both;
      seen[static_cast<size_t>(x)] = true;
    } else {
      std::vector<int> keep;
      std::set_intersection(cand[static_cast<size_t>(x)].begin(), cand[static_cast<size_t>(x)].end(), both.begin(),
                            both.end(), std::back_inserter(keep));
      cand[static_cast<size_t>(x)] = keep;
    }
  }
  const size_t k = ts.agents.size();
  if (k < 2) return ts;
  ts.turn_bit.assign(k, -1);
  for (size_t x = 0; x < k; ++x) {
    if (cand[x].size() != 1) return ts;
    ts.turn_bit[x] = cand[x][0];
  }
  // The next agent: the one turn atom each action adds (the same for all of an agent's actions).
  ts.next.assign(k, -1);
  for (pddl::ActionId a = 0; a < na; ++a) {
    const int x = ts.agent_of[static_cast<size_t>(a)];
    int nxt = -1, count = 0;
    for (int b : sorted(task.action(a).eff.add))
      for (size_t y = 0; y < k; ++y)
        if (static_cast<int>(y) != x && ts.turn_bit[y] == b) {
          nxt = static_cast<int>(y);
          ++count;
        }
    if (count != 1 || !task.action(a).cond_eff.empty()) return ts;
    if (ts.next[static_cast<size_t>(x)] >= 0 && ts.next[static_cast<size_t>(x)] != nxt) return ts;
    ts.next[static_cast<size_t>(x)] = nxt;
  }
  // Exactly one turn atom holds initially (the actions keep it so).
  const pddl::State s0 = task.initial_state();
  int on = 0;
  for (size_t x = 0; x < k; ++x) on += pddl::get_bit(s0.data(), ts.turn_bit[x]) ? 1 : 0;
  if (on != 1) return ts;
  ts.ok = true;
  return ts;
}

int TurnStructure::active(const uint64_t* s) const {
  int found = -1;
  for (size_t x = 0; x < turn_bit.size(); ++x)
    if (pddl::get_bit(s, turn_bit[x])) {
      if (found >= 0) return -1;
      found = static_cast<int>(x);
    }
  return found;
}

}  // namespace clips::heuristics
