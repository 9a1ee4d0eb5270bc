#include "heuristics/relaxed.hpp"

#include "heuristics/conditions.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

namespace clips::heuristics {

using CNode = pddl::Task::CNode;

namespace {

// What of the relaxation follows from the task and the options alone (not
// the goal's positive part, not the costs): the turn structure, the negation
// atoms and each action's relaxed preconditions, adds and killers. A
// hypothesis, a sparing or handing plan and an assistance decision each
// prepare a heuristic for a specification of their own; they share this.
struct RelaxedBase {
  TurnStructure turns;
  bool use_turns = false;
  std::vector<char> is_turn, deleted;
  std::vector<int> neg_atom, negated;
  std::vector<std::vector<int>> pre, add, killers;  // per action
  std::vector<std::vector<int>> axiom_pre;          // per axiom clause
  std::vector<int> axiom_head;
};

// The negation atoms `goal_literals` (negative literals as -b - 1) add to
// those of the actions: none unless the goal negates an atom no action's
// precondition negates.
bool goal_adds_negations(const RelaxedBase& b, const pddl::Task& t, const std::vector<std::vector<int>>& goal_literals) {
  for (const auto& c : goal_literals)
    for (int l : c) {
      if (l >= 0) continue;
      const size_t x = static_cast<size_t>(-l - 1);
      if (b.deleted[x] && !b.is_turn[x] && !t.is_derived(static_cast<int>(x)) && b.neg_atom[x] < 0) return true;
    }
  return false;
}

RelaxedBase make_base(const pddl::Task& t, const RelaxedTask::Options& opts,
                      const std::vector<std::vector<int>>& goal_literals) {
  const int na = t.num_actions(), nb = t.num_atoms();
  RelaxedBase r;
  if (opts.turns) {
    r.turns = TurnStructure::of(t);
    r.use_turns = r.turns.ok;
  }
  std::vector<char>& is_turn = r.is_turn;
  is_turn.assign(static_cast<size_t>(nb), 0);
  if (r.use_turns)
    for (int b : r.turns.turn_bit) is_turn[static_cast<size_t>(b)] = 1;
  std::vector<char>& deleted = r.deleted;
  deleted.assign(static_cast<size_t>(nb), 0);
  if (opts.dead_preconditions || opts.negations)
    for (pddl::ActionId a = 0; a < na; ++a) {
      for (int b : t.action(a).eff.del) deleted[static_cast<size_t>(b)] = 1;
      for (const auto& ce : t.action(a).cond_eff)
        for (int b : ce.eff.del) deleted[static_cast<size_t>(b)] = 1;
    }
  // A derived atom becomes false whenever its rules stop holding: never a
  // dead precondition. Nor an atom of its own when negated: nothing "adds"
  // its negation, so that literal is dropped instead.
  for (int b = 0; b < nb; ++b)
    if (t.is_derived(b)) deleted[static_cast<size_t>(b)] = 1;

  // Negation atoms: negative preconditions some action deletes (turn atoms
  // are out of the relaxation anyway).
  std::vector<int>& neg_atom = r.neg_atom;
  neg_atom.assign(static_cast<size_t>(nb), -1);
  if (opts.negations) {
    std::vector<int> p, neg;
    for (pddl::ActionId a = 0; a < na; ++a) {
      p.clear();
      neg.clear();
      conjuncts(t, t.action(a).pre, p, &neg);
      for (int b : neg)
        if (deleted[static_cast<size_t>(b)] && !is_turn[static_cast<size_t>(b)] && !t.is_derived(b) &&
            neg_atom[static_cast<size_t>(b)] < 0) {
          neg_atom[static_cast<size_t>(b)] = nb + static_cast<int>(r.negated.size());
          r.negated.push_back(b);
        }
    }
    // The goal's negative literals too ((not (rcnot g)) for every gate done):
    // "not b" is a goal atom when some action deletes b, else dropped.
    for (const auto& c : goal_literals)
      for (int l : c) {
        if (l >= 0) continue;
        const int b = -l - 1;
        if (deleted[static_cast<size_t>(b)] && !is_turn[static_cast<size_t>(b)] && !t.is_derived(b) &&
            neg_atom[static_cast<size_t>(b)] < 0) {
          neg_atom[static_cast<size_t>(b)] = nb + static_cast<int>(r.negated.size());
          r.negated.push_back(b);
        }
      }
  }
  r.pre.resize(static_cast<size_t>(na));
  r.add.resize(static_cast<size_t>(na));
  r.killers.resize(static_cast<size_t>(na));
  for (pddl::ActionId a = 0; a < na; ++a) {
    const pddl::GroundAction& ga = t.action(a);
    std::vector<int> p, neg, e;
    conjuncts(t, ga.pre, p, &neg);
    if (opts.dead_preconditions)
      for (int b : neg)
        if (!deleted[static_cast<size_t>(b)]) r.killers[static_cast<size_t>(a)].push_back(b);
    if (r.use_turns) std::erase_if(p, [&](int b) { return is_turn[static_cast<size_t>(b)] != 0; });
    for (int b : neg)
      if (neg_atom[static_cast<size_t>(b)] >= 0) p.push_back(neg_atom[static_cast<size_t>(b)]);
    if (opts.dedup_preconditions) normalise(p);
    e = ga.eff.add;
    for (const auto& ce : ga.cond_eff) e.insert(e.end(), ce.eff.add.begin(), ce.eff.add.end());
    if (r.use_turns) std::erase_if(e, [&](int b) { return is_turn[static_cast<size_t>(b)] != 0; });
    if (!r.negated.empty()) {
      for (int b : ga.eff.del)
        if (neg_atom[static_cast<size_t>(b)] >= 0) e.push_back(neg_atom[static_cast<size_t>(b)]);
      for (const auto& ce : ga.cond_eff)
        for (int b : ce.eff.del)
          if (neg_atom[static_cast<size_t>(b)] >= 0) e.push_back(neg_atom[static_cast<size_t>(b)]);
    }
    r.pre[static_cast<size_t>(a)] = std::move(p);
    r.add[static_cast<size_t>(a)] = std::move(e);
  }
  // Derived predicates' rules: zero-cost operators adding their atom, one per
  // clause (conditions.hpp), after the actions.
  for (int i = 0; i < t.num_axioms(); ++i) {
    const pddl::Axiom& x = t.axiom(i);
    for (auto& clause : axiom_clauses(t, x.body)) {
      std::vector<int> p;
      for (int b : clause)
        if (!r.use_turns || !is_turn[static_cast<size_t>(b)]) p.push_back(b);
      r.axiom_pre.push_back(std::move(p));
      r.axiom_head.push_back(x.head);
    }
  }
  return r;
}

// One base per live task and options (entries of tasks that are gone are
// dropped), for goals that add no negation atom of their own.
std::shared_ptr<const RelaxedBase> shared_base(const std::shared_ptr<const pddl::Task>& task,
                                               const RelaxedTask::Options& opts) {
  const int key = (opts.turns ? 1 : 0) | (opts.dead_preconditions ? 2 : 0) | (opts.negations ? 4 : 0) |
                  (opts.dedup_preconditions ? 8 : 0);
  static std::mutex mu;
  static std::map<std::pair<const pddl::Task*, int>,
                  std::pair<std::weak_ptr<const pddl::Task>, std::shared_ptr<const RelaxedBase>>>
      cache;
  {
    std::lock_guard lock(mu);
    auto it = cache.find({task.get(), key});
    if (it != cache.end() && it->second.first.lock() == task) return it->second.second;
  }
  auto base = std::make_shared<const RelaxedBase>(make_base(*task, opts, {}));
  std::lock_guard lock(mu);
  for (auto it = cache.begin(); it != cache.end();)
    it = it->second.first.expired() ? cache.erase(it) : std::next(it);
  cache[{task.get(), key}] = {task, base};
  return base;
}

}  // namespace

RelaxedTask RelaxedTask::of(const model::Specification& spec, Options opts) {
  const pddl::Task& t = spec.task();
  const int na = t.num_actions(), nb = t.num_atoms();
  RelaxedTask r;
  r.options = opts;
  std::vector<std::vector<int>> goal_literals;
  if (opts.negations) goal_literals = goal_dnf_literals(spec.goal());
  std::shared_ptr<const RelaxedBase> base;
  if (spec.task_ptr()) base = shared_base(spec.task_ptr(), opts);
  if (!base || goal_adds_negations(*base, t, goal_literals))
    base = std::make_shared<const RelaxedBase>(make_base(t, opts, goal_literals));
  r.turns = base->turns;
  r.use_turns = base->use_turns;
  const std::vector<char>& is_turn = base->is_turn;
  const std::vector<int>& neg_atom = base->neg_atom;
  r.negated = base->negated;
  r.num_state_atoms = nb;
  const int ntotal = nb + static_cast<int>(r.negated.size());
  r.num_atoms = ntotal;
  std::vector<std::vector<int>> pre_rows, add_rows, needed(static_cast<size_t>(ntotal)),
      kills(static_cast<size_t>(ntotal));
  const std::vector<std::vector<int>>& killers_rows = base->killers;
  const size_t nagents = r.use_turns ? r.turns.agents.size() : 0;
  r.agent_safe_min.assign(nagents, model::kInf);
  r.agent_killable.assign(nagents, {});
  for (pddl::ActionId a = 0; a < na; ++a) {
    const std::vector<int>& p = base->pre[static_cast<size_t>(a)];
    const std::vector<int>& e = base->add[static_cast<size_t>(a)];
    const double c = spec.cost(a);
    if (r.use_turns) {
      const size_t x = static_cast<size_t>(r.turns.agent_of[static_cast<size_t>(a)]);
      if (killers_rows[static_cast<size_t>(a)].empty()) r.agent_safe_min[x] = std::min(r.agent_safe_min[x], c);
      else r.agent_killable[x].push_back({c, a});
    }
    if (e.empty() && !opts.keep_empty_ops) continue;
    const int op = static_cast<int>(r.op_action.size());
    r.op_action.push_back(a);
    r.cost.push_back(c);
    r.positive_costs &= c > 0;
    r.agent.push_back(r.use_turns ? r.turns.agent_of[static_cast<size_t>(a)] : -1);
    for (int b : p) needed[static_cast<size_t>(b)].push_back(op);
    for (int b : killers_rows[static_cast<size_t>(a)]) kills[static_cast<size_t>(b)].push_back(op);
    if (p.empty()) r.no_pre_ops.push_back(op);
    pre_rows.push_back(p);
    add_rows.push_back(e);
  }
  for (auto& k : r.agent_killable) std::sort(k.begin(), k.end());
  for (size_t i = 0; i < base->axiom_pre.size(); ++i) {
    const std::vector<int>& p = base->axiom_pre[i];
    const int op = static_cast<int>(r.op_action.size());
    r.op_action.push_back(-1);
    r.cost.push_back(0);
    r.positive_costs = false;
    r.agent.push_back(-1);
    for (int b : p) needed[static_cast<size_t>(b)].push_back(op);
    if (p.empty()) r.no_pre_ops.push_back(op);
    pre_rows.push_back(p);
    add_rows.push_back({base->axiom_head[i]});
  }

  if (opts.negations) {
    for (auto& c : goal_literals) {
      std::vector<int> atoms;
      for (int l : c)
        if (l >= 0) atoms.push_back(l);
        else if (neg_atom[static_cast<size_t>(-l - 1)] >= 0) atoms.push_back(neg_atom[static_cast<size_t>(-l - 1)]);
      r.goal_clauses.push_back(std::move(atoms));
    }
    normalise_all(r.goal_clauses);
  } else {
    r.goal_clauses = goal_dnf(spec.goal(), opts.normalise_goal);
  }
  if (r.use_turns) {
    // Negation atoms (b >= nb) are never turn atoms.
    for (auto& c : r.goal_clauses) std::erase_if(c, [&](int b) { return b < nb && is_turn[static_cast<size_t>(b)] != 0; });
    if (opts.normalise_goal) normalise_all(r.goal_clauses);
  }
  for (const auto& c : r.goal_clauses) {
    r.goal_trivial |= c.empty();
    r.goal_atoms.insert(r.goal_atoms.end(), c.begin(), c.end());
  }
  normalise(r.goal_atoms);

  if (opts.relevant_only) {
    // Backward from the goal's atoms: the operators adding a relevant atom,
    // and their preconditions.
    const size_t nops = pre_rows.size();
    std::vector<std::vector<int>> adders(static_cast<size_t>(ntotal));
    for (size_t op = 0; op < nops; ++op)
      for (int e : add_rows[op]) adders[static_cast<size_t>(e)].push_back(static_cast<int>(op));
    std::vector<char> atom_rel(static_cast<size_t>(ntotal), 0), op_rel(nops, 0);
    std::vector<int> work;
    for (int b : r.goal_atoms)
      if (!atom_rel[static_cast<size_t>(b)]) {
        atom_rel[static_cast<size_t>(b)] = 1;
        work.push_back(b);
      }
    while (!work.empty()) {
      const int b = work.back();
      work.pop_back();
      for (int op : adders[static_cast<size_t>(b)]) {
        if (op_rel[static_cast<size_t>(op)]) continue;
        op_rel[static_cast<size_t>(op)] = 1;
        for (int p : pre_rows[static_cast<size_t>(op)])
          if (!atom_rel[static_cast<size_t>(p)]) {
            atom_rel[static_cast<size_t>(p)] = 1;
            work.push_back(p);
          }
      }
    }
    // Renumber the kept operators, in order.
    std::vector<int> keep_id(nops, -1);
    std::vector<std::vector<int>> pre2, add2;
    RelaxedTask k;
    for (size_t op = 0; op < nops; ++op) {
      if (!op_rel[op]) continue;
      keep_id[op] = static_cast<int>(pre2.size());
      pre2.push_back(std::move(pre_rows[op]));
      add2.push_back(std::move(add_rows[op]));
      k.op_action.push_back(r.op_action[op]);
      k.cost.push_back(r.cost[op]);
      k.agent.push_back(r.agent[op]);
    }
    r.op_action = std::move(k.op_action);
    r.cost = std::move(k.cost);
    r.agent = std::move(k.agent);
    pre_rows = std::move(pre2);
    add_rows = std::move(add2);
    r.positive_costs = true;
    for (double c : r.cost) r.positive_costs &= c > 0;
    auto remap = [&](std::vector<std::vector<int>>& lists) {
      for (auto& l : lists) {
        std::vector<int> out;
        for (int op : l)
          if (keep_id[static_cast<size_t>(op)] >= 0) out.push_back(keep_id[static_cast<size_t>(op)]);
        l = std::move(out);
      }
    };
    remap(needed);
    remap(kills);
    std::vector<int> no_pre;
    for (int op : r.no_pre_ops)
      if (keep_id[static_cast<size_t>(op)] >= 0) no_pre.push_back(keep_id[static_cast<size_t>(op)]);
    r.no_pre_ops = std::move(no_pre);
  }
  to_csr(pre_rows, r.pre_begin, r.pre);
  to_csr(add_rows, r.add_begin, r.add);
  to_csr(needed, r.needed_begin, r.needed_by);
  to_csr(kills, r.kill_begin, r.kill);
  to_csr(killers_rows, r.killers_begin, r.killers);
  return r;
}

bool RelaxedTask::killed(pddl::ActionId a, const uint64_t* s) const {
  for (int k = killers_begin[static_cast<size_t>(a)]; k < killers_begin[static_cast<size_t>(a) + 1]; ++k)
    if (pddl::get_bit(s, killers[static_cast<size_t>(k)])) return true;
  return false;
}

double RelaxedTask::turn_cost(int x, const uint64_t* s) const {
  double best = agent_safe_min[static_cast<size_t>(x)];
  for (const auto& [c, a] : agent_killable[static_cast<size_t>(x)]) {
    if (c >= best) break;
    if (!killed(a, s)) return c;
  }
  return best;
}

int min_turns(const std::vector<int>& order, const std::vector<int>& count, int k) {
  int L = 0;
  for (int i = 0; i < static_cast<int>(order.size()); ++i) {
    const int n = count[static_cast<size_t>(order[static_cast<size_t>(i)])];
    if (n > 0) L = std::max(L, (n - 1) * k + i + 1);
  }
  return L;
}

}  // namespace clips::heuristics
