#include "heuristics/basic.hpp"

#include <algorithm>
#include <queue>

namespace clips::heuristics {

using model::kInf;
using CNode = pddl::Task::CNode;

namespace {

void positive_conjuncts(const pddl::Task& t, pddl::CondId c, std::vector<int>& out) {
  const CNode& n = t.cnode(c);
  if (n.op == CNode::Atom) out.push_back(n.a);
  if (n.op == CNode::And)
    for (int i = 0; i < n.b; ++i) positive_conjuncts(t, t.ckids()[n.a + i], out);
}

// DNF of a condition over positive atoms; anything else counts as true.
std::vector<std::vector<int>> dnf(const pddl::CompiledCondition& g, pddl::CondId c) {
  const CNode& n = g.cnode(c);
  switch (n.op) {
    case CNode::False: return {};
    case CNode::Atom: return {{n.a}};
    case CNode::Or: {
      std::vector<std::vector<int>> out;
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i]);
        out.insert(out.end(), k.begin(), k.end());
      }
      return out;
    }
    case CNode::And: {
      std::vector<std::vector<int>> acc{{}};
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i]);
        std::vector<std::vector<int>> next;
        for (auto& a : acc)
          for (auto& b : k) {
            auto m = a;
            m.insert(m.end(), b.begin(), b.end());
            next.push_back(std::move(m));
          }
        acc = std::move(next);
        if (acc.size() > 4096) return {{}};  // too large: give up (0 is admissible)
      }
      return acc;
    }
    default: return {{}};
  }
}

}  // namespace

Relaxation Relaxation::of(const model::Specification& spec) {
  const pddl::Task& t = spec.task();
  const int na = t.num_actions(), nb = t.num_atoms();
  Relaxation r;
  r.pre.assign(na, {});
  r.add.assign(na, {});
  r.cost.assign(na, 0);
  r.needed_by.assign(nb, {});
  for (int a = 0; a < na; ++a) {
    positive_conjuncts(t, t.action(a).pre, r.pre[a]);
    r.add[a] = t.action(a).eff.add;
    for (auto& ce : t.action(a).cond_eff) r.add[a].insert(r.add[a].end(), ce.eff.add.begin(), ce.eff.add.end());
    r.cost[a] = spec.cost(a);
    for (int p : r.pre[a]) r.needed_by[p].push_back(a);
  }
  r.goal_clauses = dnf(spec.goal(), spec.goal().root());
  return r;
}

void HMaxHeuristic::prepare(const model::Specification& spec, const pddl::State&) {
  if (spec_ == &spec) return;
  spec_ = &spec;
  r_ = Relaxation::of(spec);
  const pddl::Task& t = spec.task();
  atom_cost_.assign(t.num_atoms(), kInf);
  act_cost_.assign(t.num_actions(), kInf);
  unsat_.assign(t.num_actions(), 0);
}

double HMaxHeuristic::estimate(const uint64_t* s) {
  if (!spec_) return 0;
  if (timed_out()) return 0;  // past the search's deadline: stay cheap until it stops
  if (spec_->is_goal(s)) return 0;
  const pddl::Task& t = spec_->task();
  int na = t.num_actions(), nb = t.num_atoms();
  std::fill(atom_cost_.begin(), atom_cost_.end(), kInf);
  using QE = std::pair<double, int>;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
  for (int b = 0; b < nb; ++b)
    if (pddl::get_bit(s, b)) {
      atom_cost_[b] = 0;
      q.push({0, b});
    }
  for (int a = 0; a < na; ++a) {
    unsat_[a] = static_cast<int>(r_.pre[a].size());
    act_cost_[a] = 0;
    if (unsat_[a] == 0)
      for (int b : r_.add[a])
        if (r_.cost[a] < atom_cost_[b]) {
          atom_cost_[b] = r_.cost[a];
          q.push({r_.cost[a], b});
        }
  }
  // One estimate is O(actions + atoms); on a large grounding that is long, so
  // the clock is read every few thousand queue entries when a deadline is set.
  const bool watch = deadline() != Clock::time_point::max();
  unsigned pops = 0;
  while (!q.empty()) {
    if (watch && (++pops & 4095) == 0 && out_of_time()) return 0;
    auto [c, b] = q.top();
    q.pop();
    if (c > atom_cost_[b]) continue;
    for (int a : r_.needed_by[b]) {
      act_cost_[a] = std::max(act_cost_[a], c);
      if (--unsat_[a] == 0) {
        double ac = act_cost_[a] + r_.cost[a];
        for (int e : r_.add[a])
          if (ac < atom_cost_[e]) {
            atom_cost_[e] = ac;
            q.push({ac, e});
          }
      }
    }
  }
  double best = kInf;
  for (auto& clause : r_.goal_clauses) {
    double m = 0;
    for (int b : clause) m = std::max(m, atom_cost_[b]);
    best = std::min(best, m);
  }
  return best;
}

void FFHeuristic::prepare(const model::Specification& spec, const pddl::State&) {
  if (spec_ == &spec) return;
  spec_ = &spec;
  r_ = Relaxation::of(spec);
  const pddl::Task& t = spec.task();
  const int na = t.num_actions(), nb = t.num_atoms();
  atom_cost_.assign(nb, kInf);
  act_cost_.assign(na, 0);
  unsat_.assign(na, 0);
  supporter_.assign(nb, -1);
  in_plan_.assign(na, 0);
  atom_done_.assign(nb, 0);
}

double FFHeuristic::estimate(const uint64_t* s) {
  if (!spec_) return 0;
  if (timed_out()) return 0;
  if (spec_->is_goal(s)) return 0;
  const pddl::Task& t = spec_->task();
  const int na = t.num_actions(), nb = t.num_atoms();
  // h_add with best supporters (Dijkstra over atoms; an action's cost is the
  // sum of its preconditions' costs plus its own).
  std::fill(atom_cost_.begin(), atom_cost_.end(), kInf);
  std::fill(supporter_.begin(), supporter_.end(), -1);
  using QE = std::pair<double, int>;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
  for (int b = 0; b < nb; ++b)
    if (pddl::get_bit(s, b)) {
      atom_cost_[b] = 0;
      q.push({0, b});
    }
  auto relax = [&](int a) {
    const double ac = act_cost_[a] + r_.cost[a];
    for (int e : r_.add[a])
      if (ac < atom_cost_[e]) {
        atom_cost_[e] = ac;
        supporter_[e] = a;
        q.push({ac, e});
      }
  };
  for (int a = 0; a < na; ++a) {
    unsat_[a] = static_cast<int>(r_.pre[a].size());
    act_cost_[a] = 0;
    if (unsat_[a] == 0) relax(a);
  }
  const bool watch = deadline() != Clock::time_point::max();
  unsigned pops = 0;
  while (!q.empty()) {
    if (watch && (++pops & 4095) == 0 && out_of_time()) return 0;
    auto [c, b] = q.top();
    q.pop();
    if (c > atom_cost_[b]) continue;
    for (int a : r_.needed_by[b]) {
      act_cost_[a] += c;
      if (--unsat_[a] == 0) relax(a);
    }
  }
  // The cheapest goal clause by h_add, then its relaxed plan.
  const std::vector<int>* best = nullptr;
  double best_cost = kInf;
  for (auto& clause : r_.goal_clauses) {
    double sum = 0;
    for (int b : clause) sum += atom_cost_[b];
    if (sum < best_cost) best_cost = sum, best = &clause;
  }
  if (!best || best_cost >= kInf) return kInf;
  std::fill(in_plan_.begin(), in_plan_.end(), 0);
  std::fill(atom_done_.begin(), atom_done_.end(), 0);
  double h = 0;
  std::vector<int> open(best->begin(), best->end());
  while (!open.empty()) {
    const int b = open.back();
    open.pop_back();
    if (atom_done_[b]) continue;
    atom_done_[b] = 1;
    const int a = supporter_[b];
    if (a < 0 || in_plan_[a]) continue;  // true in s, or already planned
    in_plan_[a] = 1;
    h += r_.cost[a];
    for (int p : r_.pre[a]) open.push_back(p);
  }
  return h;
}

}  // namespace clips::heuristics
