#include "heuristics/lmcut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "heuristics/basic.hpp"
#include "heuristics/conditions.hpp"
#include "heuristics/mutex.hpp"

namespace clips::heuristics {

using model::kInf;

namespace {

constexpr int64_t kUnset = std::numeric_limits<int64_t>::max();

// The smallest k in 1..1000 making every cost * k integral (relative
// tolerance: 0.6 * 5 = 3.0000000000000004 counts), else 1000 (the costs are
// then rounded down: an admissible under-estimate).
int cost_scale_of(const std::vector<double>& costs) {
  for (int k = 1; k <= 1000; ++k) {
    bool ok = true;
    for (double c : costs) {
      const double v = c * k;
      if (std::abs(v - std::round(v)) > 1e-9 * std::max(1.0, std::abs(v))) {
        ok = false;
        break;
      }
    }
    if (ok) return k;
  }
  return 1000;
}

int64_t scaled_cost(double c, int scale) {
  if (!(c > 0)) return 0;  // negative or NaN costs cannot occur; 0 is safe
  const double v = c * scale;
  const double r = std::round(v);
  // Within the tolerance of an integer: that integer; else round down.
  return static_cast<int64_t>(std::abs(v - r) <= 1e-9 * std::max(1.0, v) ? r : std::floor(v));
}

}  // namespace

void LmCutHeuristic::prepare(const model::Specification& spec, const pddl::State&) {
  if (spec_ == &spec) return;
  spec_ = &spec;
  RelaxedTask::Options o;
  o.turns = turns_;
  o.dead_preconditions = o.dedup_preconditions = o.normalise_goal = o.relevant_only = true;
  o.negations = negations_;
  r_ = RelaxedTask::of(spec, o);
  // Goal clauses asking for two atoms no reachable state has together can
  // never hold: leave them out (all of them: the goal is unreachable).
  if (const auto mutexes = MutexTable::of(spec.task_ptr()); !r_.goal_clauses.empty())
    std::erase_if(r_.goal_clauses, [&](const std::vector<int>& c) {
      std::vector<int> state_atoms;  // the task's own (not negation atoms)
      for (int b : c)
        if (b < r_.num_state_atoms) state_atoms.push_back(b);
      return mutexes->any_mutex(state_atoms);
    });
  r_.goal_trivial = false;
  for (const auto& c : r_.goal_clauses) r_.goal_trivial |= c.empty();
  num_atoms_ = r_.num_atoms;
  init_prop_ = num_atoms_;
  goal_prop_ = num_atoms_ + 1;
  num_props_ = num_atoms_ + 2;
  {
    std::vector<double> costs;
    for (pddl::ActionId a = 0; a < spec.task().num_actions(); ++a) costs.push_back(spec.cost(a));
    scale_ = cost_scale_of(costs);
  }

  std::vector<std::vector<int>> pre, eff;
  std::vector<int64_t> cost;
  const size_t nrel = r_.op_action.size();
  for (size_t op = 0; op < nrel; ++op) {
    std::vector<int> p(r_.pre.begin() + r_.pre_begin[op], r_.pre.begin() + r_.pre_begin[op + 1]), e;
    for (int k = r_.add_begin[op]; k < r_.add_begin[op + 1]; ++k)
      if (!std::binary_search(p.begin(), p.end(), r_.add[static_cast<size_t>(k)]))  // an add it needs is no use relaxed
        e.push_back(r_.add[static_cast<size_t>(k)]);
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    if (p.empty()) p.push_back(init_prop_);
    pre.push_back(std::move(p));
    eff.push_back(std::move(e));  // kept even when empty: operator ids stay the relaxation's
    cost.push_back(scaled_cost(r_.cost[op], scale_));
  }
  for (const auto& clause : r_.goal_clauses) {
    std::vector<int> p = clause;
    if (p.empty()) p.push_back(init_prop_);
    pre.push_back(std::move(p));
    eff.push_back({goal_prop_});
    cost.push_back(0);
  }
  to_csr(pre, op_pre_begin_, op_pre_);
  to_csr(eff, op_eff_begin_, op_eff_);
  base_cost_ = cost;
  const size_t nops = pre.size();
  cost_.assign(nops, 0);
  unsat0_.resize(nops);
  for (size_t op = 0; op < nops; ++op) unsat0_[op] = static_cast<int>(pre[op].size());
  unsat_ = unsat0_;
  supporter_.assign(nops, -1);
  supporter_cost_.assign(nops, kUnset);
  seen_.assign(nops, 0);
  into_zone_.assign(nops, 0);
  round_ = 0;
  counted_.assign(nops, 0);
  estimate_stamp_ = 0;
  std::vector<std::vector<int>> pre_of(static_cast<size_t>(num_props_)), eff_of(static_cast<size_t>(num_props_));
  for (size_t op = 0; op < nops; ++op) {
    for (int p : pre[op]) pre_of[static_cast<size_t>(p)].push_back(static_cast<int>(op));
    for (int e : eff[op]) eff_of[static_cast<size_t>(e)].push_back(static_cast<int>(op));
  }
  to_csr(pre_of, pre_of_begin_, pre_of_);
  to_csr(eff_of, eff_of_begin_, eff_of_);
  hmax_.assign(static_cast<size_t>(num_props_), kUnset);
  status_.assign(static_cast<size_t>(num_props_), Unreached);
  reached_.clear();
  supported_.assign(static_cast<size_t>(num_props_), {});
  // Per agent, every action of it with its operator (or -1) and scaled cost.
  agent_actions_.assign(r_.turns.agents.size(), {});
  pure_count_.assign(r_.turns.agents.size(), 0);
  if (r_.use_turns) {
    const pddl::Task& t = spec.task();
    std::vector<int> op_of(static_cast<size_t>(t.num_actions()), -1);
    for (size_t op = 0; op < nrel; ++op)
      if (r_.op_action[op] >= 0) op_of[static_cast<size_t>(r_.op_action[op])] = static_cast<int>(op);
    for (pddl::ActionId a = 0; a < t.num_actions(); ++a)
      agent_actions_[static_cast<size_t>(r_.turns.agent_of[static_cast<size_t>(a)])].push_back(
          {op_of[static_cast<size_t>(a)], scaled_cost(spec.cost(a), scale_), a});
  }
  // h_max values are at most the sum of the costs along one chain of at most
  // num_props_ operators: buckets while that stays small.
  const int64_t max_cost = cost.empty() ? 0 : *std::max_element(cost.begin(), cost.end());
  buckets_mode_ = max_cost * static_cast<int64_t>(num_props_) <= (int64_t{1} << 20);
  buckets_.clear();
  heap_.clear();
  queued_ = 0;
  bucket_cur_ = 0;
}

void LmCutHeuristic::push(int64_t c, int p) {
  ++queued_;
  if (buckets_mode_) {
    const size_t b = static_cast<size_t>(c);
    if (b >= buckets_.size()) buckets_.resize(b + 1);
    buckets_[b].push_back(p);
    if (b < bucket_cur_) bucket_cur_ = b;
    return;
  }
  heap_.emplace_back(c, p);
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
}

void LmCutHeuristic::clear_queue() {
  for (auto& b : buckets_) b.clear();
  heap_.clear();
  queued_ = 0;
  bucket_cur_ = 0;
}

bool LmCutHeuristic::pop(int64_t& c, int& p) {
  if (queued_ == 0) {
    bucket_cur_ = 0;
    return false;
  }
  --queued_;
  if (buckets_mode_) {
    while (buckets_[bucket_cur_].empty()) ++bucket_cur_;
    c = static_cast<int64_t>(bucket_cur_);
    p = buckets_[bucket_cur_].back();
    buckets_[bucket_cur_].pop_back();
    return true;
  }
  std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
  c = heap_.back().first;
  p = heap_.back().second;
  heap_.pop_back();
  return true;
}

void LmCutHeuristic::first_exploration(const uint64_t* s) {
  for (int p : reached_) {
    status_[static_cast<size_t>(p)] = Unreached;
    hmax_[static_cast<size_t>(p)] = kUnset;
    supported_[static_cast<size_t>(p)].clear();
  }
  reached_.clear();
  const size_t nops = base_cost_.size();
  std::copy(base_cost_.begin(), base_cost_.end(), cost_.begin());
  std::copy(unsat0_.begin(), unsat0_.end(), unsat_.begin());
  std::fill(supporter_.begin(), supporter_.end(), -1);
  std::fill(supporter_cost_.begin(), supporter_cost_.end(), kUnset);
  (void)nops;
  r_.for_each_true(s, [&](int p) {
    enqueue(p, 0);
    // Operators this atom kills never become applicable.
    for (int k = r_.kill_begin[static_cast<size_t>(p)]; k < r_.kill_begin[static_cast<size_t>(p) + 1]; ++k)
      unsat_[static_cast<size_t>(r_.kill[static_cast<size_t>(k)])] = 1 << 30;
  });
  enqueue(init_prop_, 0);
  int64_t c;
  int p;
  // One exploration is O(operators); on a large grounding that is long, so
  // the clock is read every few thousand pops when a deadline is set.
  const bool watch = deadline() != Clock::time_point::max();
  unsigned pops = 0;
  while (pop(c, p)) {
    if (watch && (++pops & 4095) == 0 && out_of_time()) {
      clear_queue();
      return;
    }
    if (hmax_[static_cast<size_t>(p)] < c) continue;
    for (int k = pre_of_begin_[static_cast<size_t>(p)]; k < pre_of_begin_[static_cast<size_t>(p) + 1]; ++k) {
      const int o = pre_of_[static_cast<size_t>(k)];
      if (--unsat_[static_cast<size_t>(o)] == 0) {
        set_supporter(static_cast<size_t>(o), p, c);
        const int64_t t = c + cost_[static_cast<size_t>(o)];
        for (int j = op_eff_begin_[static_cast<size_t>(o)]; j < op_eff_begin_[static_cast<size_t>(o) + 1]; ++j)
          enqueue(op_eff_[static_cast<size_t>(j)], t);
      }
    }
  }
}

void LmCutHeuristic::incremental_exploration() {
  for (int o : cut_) {
    const int64_t t = supporter_cost_[static_cast<size_t>(o)] + cost_[static_cast<size_t>(o)];
    for (int j = op_eff_begin_[static_cast<size_t>(o)]; j < op_eff_begin_[static_cast<size_t>(o) + 1]; ++j)
      enqueue(op_eff_[static_cast<size_t>(j)], t);
  }
  int64_t c;
  int p;
  while (pop(c, p)) {
    if (hmax_[static_cast<size_t>(p)] < c) continue;
    for (int k = pre_of_begin_[static_cast<size_t>(p)]; k < pre_of_begin_[static_cast<size_t>(p) + 1]; ++k) {
      const size_t o = static_cast<size_t>(pre_of_[static_cast<size_t>(k)]);
      if (supporter_[o] != p) continue;
      const int64_t old = supporter_cost_[o];
      if (old <= c) continue;
      // The supporter got cheaper: the precondition of largest h_max now.
      int best = p;
      for (int j = op_pre_begin_[o]; j < op_pre_begin_[o + 1]; ++j) {
        const int q = op_pre_[static_cast<size_t>(j)];
        if (hmax_[static_cast<size_t>(q)] > hmax_[static_cast<size_t>(best)]) best = q;
      }
      if (best != p) set_supporter(o, best, hmax_[static_cast<size_t>(best)]);
      else supporter_cost_[o] = c;
      if (supporter_cost_[o] != old) {
        const int64_t t = supporter_cost_[o] + cost_[o];
        for (int j = op_eff_begin_[o]; j < op_eff_begin_[o + 1]; ++j) enqueue(op_eff_[static_cast<size_t>(j)], t);
      }
    }
  }
}

void LmCutHeuristic::mark_goal_plateau() {
  // Everything that reaches the goal through zero-cost operators' supporters;
  // every operator adding one of them is marked (into_zone_) for the second
  // exploration. One round per cut.
  if (++round_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    std::fill(into_zone_.begin(), into_zone_.end(), 0);
    round_ = 1;
  }
  stack_.clear();
  stack_.push_back(goal_prop_);
  while (!stack_.empty()) {
    const int p = stack_.back();
    stack_.pop_back();
    if (p < 0 || status_[static_cast<size_t>(p)] == GoalZone) continue;
    status_[static_cast<size_t>(p)] = GoalZone;
    zone_.push_back(p);
    for (int k = eff_of_begin_[static_cast<size_t>(p)]; k < eff_of_begin_[static_cast<size_t>(p) + 1]; ++k) {
      const size_t o = static_cast<size_t>(eff_of_[static_cast<size_t>(k)]);
      into_zone_[o] = round_;
      if (cost_[o] == 0) stack_.push_back(supporter_[o]);
    }
  }
}

void LmCutHeuristic::second_exploration(const uint64_t* s) {
  // From the state along supporters, stopping at operators into the goal
  // zone: those form the cut.
  cut_.clear();
  stack_.clear();
  auto before = [&](int p) {
    status_[static_cast<size_t>(p)] = BeforeGoalZone;
    zone_.push_back(p);
    stack_.push_back(p);
  };
  before(init_prop_);
  r_.for_each_true(s, before);
  while (!stack_.empty()) {
    const int p = stack_.back();
    stack_.pop_back();
    const std::vector<int>& ops = supported_[static_cast<size_t>(p)];
    for (size_t k = 0; k < ops.size(); ++k) {
      const size_t o = static_cast<size_t>(ops[k]);
      if (supporter_[o] != p || seen_[o] == round_) continue;
      seen_[o] = round_;
      if (into_zone_[o] == round_) {
        cut_.push_back(static_cast<int>(o));
        continue;
      }
      for (int j = op_eff_begin_[o]; j < op_eff_begin_[o + 1]; ++j) {
        const int e = op_eff_[static_cast<size_t>(j)];
        if (status_[static_cast<size_t>(e)] != BeforeGoalZone) before(e);
      }
    }
  }
}

int64_t LmCutHeuristic::turn_bound(const uint64_t* s) {
  const int k = static_cast<int>(r_.turns.agents.size());
  const int first = r_.turns.active(s);
  if (first < 0) return 0;
  order_.clear();
  for (int x = first, i = 0; i < k && x >= 0; ++i, x = r_.turns.next[static_cast<size_t>(x)]) order_.push_back(x);
  const int L = min_turns(order_, pure_count_, k);
  if (L == 0) return 0;
  int64_t bound = 0;
  for (int i = 0; i < static_cast<int>(order_.size()); ++i) {
    const int x = order_[static_cast<size_t>(i)];
    const int turns = turns_of(L, i, k);
    if (turns == 0) continue;
    // The least residual cost of an action of x that s does not kill.
    int64_t least = kUnset;
    const auto& acts = agent_actions_[static_cast<size_t>(x)];
    for (size_t j = 0; j < acts.size() && least > 0; ++j) {
      const AgentAction& a = acts[j];
      const int64_t residual = a.op >= 0 ? cost_[static_cast<size_t>(a.op)] : a.cost;
      if (residual >= least || r_.killed(a.action, s)) continue;
      least = residual;
    }
    if (least == kUnset) return kUnset;  // x cannot act, yet the plan needs its turn: a dead end
    bound += turns * least;
  }
  return bound;
}

double LmCutHeuristic::estimate(const uint64_t* s) {
  if (!spec_) return 0;
  if (timed_out()) return 0;
  // No goal test: where the goal holds, the atoms of one of its clauses
  // hold, and the estimate is 0 without it (the goal may be large: a
  // command's existential goal is a disjunction over its groundings).
  if (r_.goal_clauses.empty()) return kInf;  // the goal is false
  if (r_.goal_trivial) return 0;
  first_exploration(s);
  if (timed_out()) return 0;  // cut short by the deadline: 0 is admissible
  if (status_[static_cast<size_t>(goal_prop_)] == Unreached) return kInf;
  if (++estimate_stamp_ == 0) {
    std::fill(counted_.begin(), counted_.end(), 0);
    estimate_stamp_ = 1;
  }
  std::fill(pure_count_.begin(), pure_count_.end(), 0);
  const size_t nrel = r_.op_action.size();
  int64_t h = 0;
  const bool watch = deadline() != Clock::time_point::max();
  unsigned rounds = 0;
  while (hmax_[static_cast<size_t>(goal_prop_)] != 0) {
    if (watch && (++rounds & 63) == 0 && out_of_time()) return 0;
    zone_.clear();
    mark_goal_plateau();
    second_exploration(s);
    int64_t cut_cost = kUnset;
    for (int o : cut_) cut_cost = std::min(cut_cost, cost_[static_cast<size_t>(o)]);
    // Cannot happen (the cut separates the state from a goal of positive
    // h_max, and costs are integral); stop with what is proven so far.
    if (cut_.empty() || cut_cost <= 0 || cut_cost == kUnset) break;
    if (r_.use_turns) {
      // A landmark of one agent's actions, sharing none with the landmarks
      // counted so far, needs one more action of that agent.
      int agent = -2;
      bool fresh = true;
      for (int o : cut_) {
        const int x = static_cast<size_t>(o) < nrel ? r_.agent[static_cast<size_t>(o)] : -1;
        if (agent == -2) agent = x;
        if (x < 0 || x != agent) agent = -1;
        fresh &= counted_[static_cast<size_t>(o)] != estimate_stamp_;
      }
      if (agent >= 0 && fresh) {
        ++pure_count_[static_cast<size_t>(agent)];
        for (int o : cut_) counted_[static_cast<size_t>(o)] = estimate_stamp_;
      }
    }
    for (int o : cut_) cost_[static_cast<size_t>(o)] -= cut_cost;
    h += cut_cost;
    for (int p : zone_) status_[static_cast<size_t>(p)] = Reached;
    incremental_exploration();
  }
  if (r_.use_turns) {
    const int64_t t = turn_bound(s);
    if (t == kUnset) return kInf;
    h += t;
  }
  return static_cast<double>(h) / scale_;
}

}  // namespace clips::heuristics
