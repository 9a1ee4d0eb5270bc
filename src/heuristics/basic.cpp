#include "heuristics/basic.hpp"

#include "heuristics/conditions.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace clips::heuristics {

using model::kInf;
using CNode = pddl::Task::CNode;

Relaxation Relaxation::of(const model::Specification& spec) {
  const pddl::Task& t = spec.task();
  const int na = t.num_actions(), nb = t.num_atoms();
  Relaxation r;
  r.pre.assign(na, {});
  r.add.assign(na, {});
  r.cost.assign(na, 0);
  r.needed_by.assign(nb, {});
  for (int a = 0; a < na; ++a) {
    conjuncts(t, t.action(a).pre, r.pre[a]);
    r.add[a] = t.action(a).eff.add;
    for (auto& ce : t.action(a).cond_eff) r.add[a].insert(r.add[a].end(), ce.eff.add.begin(), ce.eff.add.end());
    r.cost[a] = spec.cost(a);
    for (int p : r.pre[a]) r.needed_by[p].push_back(a);
  }
  // Derived predicates' rules: zero-cost entries after the actions.
  for (int i = 0; i < t.num_axioms(); ++i)
    for (auto& clause : axiom_clauses(t, t.axiom(i).body)) {
      const int a = static_cast<int>(r.pre.size());
      for (int p : clause) r.needed_by[static_cast<size_t>(p)].push_back(a);
      r.pre.push_back(std::move(clause));
      r.add.push_back({t.axiom(i).head});
      r.cost.push_back(0);
    }
  r.goal_clauses = goal_dnf(spec.goal(), /*normalise=*/false);
  return r;
}

void HMaxHeuristic::prepare(const model::Specification& spec, const pddl::State&) {
  if (spec_ == &spec) return;
  spec_ = &spec;
  r_ = Relaxation::of(spec);
  const pddl::Task& t = spec.task();
  atom_cost_.assign(t.num_atoms(), kInf);
  act_cost_.assign(r_.pre.size(), kInf);
  unsat_.assign(r_.pre.size(), 0);
}

double HMaxHeuristic::estimate(const uint64_t* s) {
  if (!spec_) return 0;
  if (timed_out()) return 0;  // past the search's deadline: stay cheap until it stops
  if (spec_->is_goal(s)) return 0;
  const pddl::Task& t = spec_->task();
  const int na = static_cast<int>(r_.pre.size()), nb = t.num_atoms();
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
  RelaxedTask::Options o;
  o.relevant_only = true;  // changes no value (relaxed.hpp)
  if (turns_) {
    o.turns = o.dead_preconditions = o.dedup_preconditions = o.normalise_goal = true;
    o.negations = negations_;
  } else {
    o.keep_empty_ops = true;  // exactly the relaxation (and tie-breaking) of the plain h_FF
  }
  r_ = RelaxedTask::of(spec, o);
  const size_t nb = static_cast<size_t>(r_.num_atoms), nops = r_.op_action.size();
  atom_cost_.assign(nb, kInf);
  supporter_.assign(nb, -1);
  act_cost_.assign(nops, 0);
  unsat0_.resize(nops);
  for (size_t o2 = 0; o2 < nops; ++o2) unsat0_[o2] = r_.pre_begin[o2 + 1] - r_.pre_begin[o2];
  unsat_ = unsat0_;
  is_goal_atom_.assign(nb, 0);
  for (int b : r_.goal_atoms) is_goal_atom_[static_cast<size_t>(b)] = 1;
  atom_mark_.assign(nb, 0);
  op_mark_.assign(nops, 0);
  stamp_ = 0;
  count_.assign(r_.turns.agents.size(), 0);
  // Buckets when every cost is a positive multiple of 1/k for a small k.
  buckets_mode_ = false;
  if (r_.positive_costs && nops > 0)
    for (int k = 1; k <= 1000 && !buckets_mode_; ++k) {
      bool ok = true;
      for (double c : r_.cost) {
        const double v = c * k;
        if (std::abs(v - std::round(v)) > 1e-9 * std::max(1.0, v) || std::round(v) < 1) {
          ok = false;
          break;
        }
      }
      if (ok) {
        buckets_mode_ = true;
        bucket_scale_ = k;
      }
    }
  buckets_.clear();
  bucket_cur_ = bucket_top_ = 0;
}

// One relaxed action becomes applicable: its adds get h_add cost = the sum
// of its preconditions' costs plus its own (the best supporter is the first
// action reaching the lowest cost).
[[gnu::always_inline]] inline void FFHeuristic::relax(int op) {
  const double ac = act_cost_[static_cast<size_t>(op)] + r_.cost[static_cast<size_t>(op)];
  for (int k = r_.add_begin[static_cast<size_t>(op)]; k < r_.add_begin[static_cast<size_t>(op) + 1]; ++k) {
    const int e = r_.add[static_cast<size_t>(k)];
    if (ac < atom_cost_[static_cast<size_t>(e)]) {
      atom_cost_[static_cast<size_t>(e)] = ac;
      supporter_[static_cast<size_t>(e)] = op;
      push(ac, e);
    }
  }
}

namespace {
constexpr size_t kMaxBuckets = size_t{1} << 16;
}  // namespace

[[gnu::noinline]] void FFHeuristic::push(double c, int b) {
  if (buckets_mode_) {
    const double x = std::round(c * bucket_scale_);
    if (x < static_cast<double>(kMaxBuckets)) {
      const size_t i = static_cast<size_t>(x);
      if (i >= buckets_.size()) buckets_.resize(std::min(kMaxBuckets, std::max(i + 1, 2 * buckets_.size())));
      buckets_[i].emplace_back(c, b);
      bucket_top_ = std::max(bucket_top_, i + 1);
      return;
    }
  }
  heap_.emplace_back(c, b);
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
}

// Atom b's cost c is final: the actions needing it.
inline void FFHeuristic::process(int b, double c) {
  for (int k = r_.needed_begin[static_cast<size_t>(b)]; k < r_.needed_begin[static_cast<size_t>(b) + 1]; ++k) {
    const int op = r_.needed_by[static_cast<size_t>(k)];
    act_cost_[static_cast<size_t>(op)] += c;
    if (--unsat_[static_cast<size_t>(op)] == 0) relax(op);
  }
}

double FFHeuristic::estimate(const uint64_t* s) {
  if (!spec_) return 0;
  if (timed_out()) return 0;
  // No goal test: where the goal holds, the atoms of one of its clauses
  // hold, and the estimate is 0 without it (the goal may be large: a
  // command's existential goal is a disjunction over its groundings).
  // h_add by Dijkstra over atoms, as a priority queue of (cost, atom) pops
  // them (so with the plain relaxation every value and supporter is the
  // h_FF of before): atoms true in s first, in ascending order, then by cost.
  std::fill(atom_cost_.begin(), atom_cost_.end(), kInf);
  std::fill(supporter_.begin(), supporter_.end(), -1);
  std::fill(act_cost_.begin(), act_cost_.end(), 0.0);
  std::copy(unsat0_.begin(), unsat0_.end(), unsat_.begin());
  heap_.clear();
  zero_.clear();
  r_.for_each_true(s, [&](int b) {
    atom_cost_[static_cast<size_t>(b)] = 0;
    zero_.push_back(b);
    // Actions this atom kills never become applicable (their count never reaches 0).
    for (int k = r_.kill_begin[static_cast<size_t>(b)]; k < r_.kill_begin[static_cast<size_t>(b) + 1]; ++k)
      unsat_[static_cast<size_t>(r_.kill[static_cast<size_t>(k)])] = 1 << 30;
  });
  // With every cost positive, nothing is pushed at cost 0, so the atoms of s
  // are the queue's first pops in ascending order; with zero-cost actions
  // they go through the queue.
  if (!r_.positive_costs)
    for (int b : zero_) heap_.emplace_back(0.0, b);
  std::make_heap(heap_.begin(), heap_.end(), std::greater<>());
  for (int op : r_.no_pre_ops)
    if (unsat_[static_cast<size_t>(op)] == 0) relax(op);
  // Once every goal atom's cost is final, so are the supporters the relaxed
  // plan reads (each was popped before what it supports): stop there.
  goal_left_ = static_cast<int>(r_.goal_atoms.size());
  bool done = goal_left_ == 0;
  if (r_.positive_costs)
    for (int b : zero_) {
      if (is_goal_atom_[static_cast<size_t>(b)] && --goal_left_ == 0) {
        done = true;
        break;
      }
      process(b, 0.0);
    }
  const bool watch = deadline() != Clock::time_point::max();
  unsigned pops = 0;
  bool stopped = false;
  // Buckets in order, then whatever the heap holds (costs past the buckets).
  // (Pushes go to later buckets and may move the bucket list: index it.)
  for (bucket_cur_ = 0; !done && bucket_cur_ < bucket_top_; ++bucket_cur_) {
    if (buckets_[bucket_cur_].size() > 1) std::sort(buckets_[bucket_cur_].begin(), buckets_[bucket_cur_].end());
    for (size_t i = 0; i < buckets_[bucket_cur_].size(); ++i) {
      if (watch && (++pops & 4095) == 0 && out_of_time()) {
        stopped = true;
        break;
      }
      const auto [c, b] = buckets_[bucket_cur_][i];
      if (c > atom_cost_[static_cast<size_t>(b)]) continue;
      if (is_goal_atom_[static_cast<size_t>(b)] && --goal_left_ == 0) {
        done = true;
        break;
      }
      process(b, c);
    }
    if (stopped) break;
  }
  for (size_t i = 0; i < bucket_top_; ++i) buckets_[i].clear();
  bucket_top_ = 0;
  if (stopped) return 0;
  while (!done && !heap_.empty()) {
    if (watch && (++pops & 4095) == 0 && out_of_time()) return 0;
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const auto [c, b] = heap_.back();
    heap_.pop_back();
    if (c > atom_cost_[static_cast<size_t>(b)]) continue;
    if (is_goal_atom_[static_cast<size_t>(b)] && --goal_left_ == 0) break;
    process(b, c);
  }
  // The cheapest goal clause by h_add, then its relaxed plan.
  const std::vector<int>* best = nullptr;
  double best_cost = kInf;
  for (auto& clause : r_.goal_clauses) {
    double sum = 0;
    for (int b : clause) sum += atom_cost_[static_cast<size_t>(b)];
    if (sum < best_cost) best_cost = sum, best = &clause;
  }
  if (!best || best_cost >= kInf) return kInf;
  if (++stamp_ == 0) {
    std::fill(atom_mark_.begin(), atom_mark_.end(), 0);
    std::fill(op_mark_.begin(), op_mark_.end(), 0);
    stamp_ = 1;
  }
  double h = 0;
  open_.assign(best->begin(), best->end());
  while (!open_.empty()) {
    const int b = open_.back();
    open_.pop_back();
    if (atom_mark_[static_cast<size_t>(b)] == stamp_) continue;
    atom_mark_[static_cast<size_t>(b)] = stamp_;
    const int op = supporter_[static_cast<size_t>(b)];
    if (op < 0 || op_mark_[static_cast<size_t>(op)] == stamp_) continue;  // true in s, or already planned
    op_mark_[static_cast<size_t>(op)] = stamp_;
    h += r_.cost[static_cast<size_t>(op)];
    if (r_.use_turns && r_.agent[static_cast<size_t>(op)] >= 0) ++count_[static_cast<size_t>(r_.agent[static_cast<size_t>(op)])];
    for (int k = r_.pre_begin[static_cast<size_t>(op)]; k < r_.pre_begin[static_cast<size_t>(op) + 1]; ++k)
      open_.push_back(r_.pre[static_cast<size_t>(k)]);
  }
  if (r_.use_turns) {
    // The turns alternation forces besides the relaxed plan's own actions,
    // each at its agent's cheapest usable action.
    const int k = static_cast<int>(r_.turns.agents.size());
    const int first = r_.turns.active(s);
    if (first >= 0) {
      order_.clear();
      for (int x = first, i = 0; i < k && x >= 0; ++i, x = r_.turns.next[static_cast<size_t>(x)]) order_.push_back(x);
      const int L = min_turns(order_, count_, k);
      for (int i = 0; i < static_cast<int>(order_.size()); ++i) {
        const int x = order_[static_cast<size_t>(i)];
        const int fills = turns_of(L, i, k) - count_[static_cast<size_t>(x)];
        if (fills > 0) h += fills * r_.turn_cost(x, s);
      }
    }
    std::fill(count_.begin(), count_.end(), 0);
  }
  return h;
}

}  // namespace clips::heuristics
