#include "domains/strips.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "util/error.hpp"

namespace clips::domains {

namespace {

using CNode = pddl::Task::CNode;
constexpr size_t kLimit = 100000;

// A literal: atom bit * 2 + (1 if negated); a clause: sorted literals.
using Clause = std::vector<int>;
using Dnf = std::vector<Clause>;

bool consistent(const Clause& c) {
  for (size_t i = 1; i < c.size(); ++i)
    if ((c[i] >> 1) == (c[i - 1] >> 1)) return false;  // p and not p
  return true;
}

Clause merged(const Clause& a, const Clause& b) {
  Clause m;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(m));
  return m;
}

Dnf product(const Dnf& a, const Dnf& b) {
  Dnf out;
  for (const Clause& x : a)
    for (const Clause& y : b) {
      Clause m = merged(x, y);
      if (!consistent(m)) continue;
      out.push_back(std::move(m));
      if (out.size() > kLimit) throw InputError("export-strips: a condition has more than 100,000 DNF clauses");
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// DNF of a compiled condition (negated when `neg`) over literals; `node`
// reads a node and `kid` the i-th kid of a junction.
template <class Node, class Kid>
Dnf dnf(int c, bool neg, const Node& node, const Kid& kid) {
  const CNode& n = node(c);
  switch (n.op) {
    case CNode::True: return neg ? Dnf{} : Dnf{Clause{}};
    case CNode::False: return neg ? Dnf{Clause{}} : Dnf{};
    case CNode::Atom: return {{n.a * 2 + (neg ? 1 : 0)}};
    case CNode::NotAtom: return {{n.a * 2 + (neg ? 0 : 1)}};
    case CNode::Not: return dnf(n.a, !neg, node, kid);
    case CNode::And:
    case CNode::Or: {
      // A conjunction (a negated disjunction) multiplies out, a disjunction
      // (a negated conjunction) unites.
      const bool conj = (n.op == CNode::And) != neg;
      Dnf acc = conj ? Dnf{Clause{}} : Dnf{};
      for (int i = 0; i < n.b; ++i) {
        Dnf k = dnf(kid(n.a + i), neg, node, kid);
        if (conj) {
          acc = product(acc, k);
        } else {
          acc.insert(acc.end(), k.begin(), k.end());
          if (acc.size() > kLimit) throw InputError("export-strips: a condition has more than 100,000 DNF clauses");
        }
      }
      std::sort(acc.begin(), acc.end());
      acc.erase(std::unique(acc.begin(), acc.end()), acc.end());
      return acc;
    }
    default:
      throw InputError(
          "export-strips: the task has a numeric condition; only packs with their own exporter (doors-keys-gems) "
          "export numeric tasks");
  }
}

Dnf task_dnf(const pddl::Task& t, pddl::CondId c, bool neg) {
  return dnf(c, neg, [&](int i) -> const CNode& { return t.cnode(i); }, [&](int i) { return t.ckids()[i]; });
}

// A name no other name of its kind has: `base`, else base_2, base_3, ...
std::string unique_name(const std::string& base, std::set<std::string>& taken) {
  std::string name = base;
  for (int k = 2; !taken.insert(name).second; ++k) name = base + "_" + std::to_string(k);
  return name;
}

}  // namespace

int integer_cost_scale(const std::vector<double>& costs, int max_scale) {
  for (double c : costs)
    if (!std::isfinite(c) || c < 0) throw InputError(fmt::format("action costs must be finite and >= 0, got {}", c));
  for (int k = 1; k <= max_scale; ++k) {
    bool ok = std::all_of(costs.begin(), costs.end(), [k](double c) {
      double v = c * k;
      // Relative tolerance: binary fractions like 0.6 are never exact.
      return std::abs(v - std::round(v)) <= 1e-9 * std::max(1.0, std::abs(v));
    });
    if (ok) return k;
  }
  throw InputError(fmt::format("no integer factor in 1..{} makes the action costs integral", max_scale));
}

StripsExport export_grounded_strips(const pddl::Task& task, const pddl::State& start, const std::string& goal,
                                            const model::CostProfile& costs) {
  if (task.num_fluents() > 0)
    throw InputError("export-strips: the task has numeric fluents; only packs with their own exporter "
                     "(doors-keys-gems) export numeric tasks");
  if (task.num_axioms() > 0)
    throw InputError("export-strips: the task has derived predicates (:derived), which STRIPS cannot state");
  const pddl::Domain& dom = task.domain();
  const pddl::CompiledCondition goal_cond = task.compile_text(goal, "<goal>");
  const Dnf goal_dnf =
      dnf(goal_cond.root(), false, [&](int i) -> const CNode& { return goal_cond.cnode(i); },
          [&](int i) { return goal_cond.ckids()[i]; });
  if (goal_dnf.empty()) throw InputError("export-strips: the goal " + goal + " can never hold in this problem");

  // ---- costs (as model::Specification reads a profile)
  const int na = task.num_actions();
  std::vector<double> cost(static_cast<size_t>(na));
  if (costs.default_cost < 0 && !dom.total_cost)
    throw InputError("export-strips: cost profile 'task' needs the domain's own action costs (total-cost)");
  for (pddl::ActionId a = 0; a < na; ++a) {
    const auto& ga = task.action(a);
    cost[static_cast<size_t>(a)] =
        costs.default_cost < 0
            ? ga.cost
            : costs.cost(ga.args.empty() ? "" : task.object_name(ga.args[0]), dom.actions[ga.schema].name);
  }
  const int scale = integer_cost_scale(cost);

  // ---- actions: one variant per precondition clause and firing pattern
  struct Variant {
    pddl::ActionId action;
    Clause pre;
    std::vector<int> add, del;  // final adds; deletes not re-added
  };
  std::vector<Variant> variants;
  std::vector<int> variant_count(static_cast<size_t>(na), 0);
  for (pddl::ActionId a = 0; a < na; ++a) {
    const auto& ga = task.action(a);
    struct Partial {
      Clause pre;
      std::vector<size_t> fired;
    };
    std::vector<Partial> parts;
    for (Clause& c : task_dnf(task, ga.pre, false)) parts.push_back({std::move(c), {}});
    for (size_t i = 0; i < ga.cond_eff.size() && !parts.empty(); ++i) {
      const Dnf yes = task_dnf(task, ga.cond_eff[i].cond, false), no = task_dnf(task, ga.cond_eff[i].cond, true);
      std::vector<Partial> next;
      for (const Partial& p : parts) {
        for (bool fires : {true, false})
          for (const Clause& c : fires ? yes : no) {
            Clause m = merged(p.pre, c);
            if (!consistent(m)) continue;
            Partial q{std::move(m), p.fired};
            if (fires) q.fired.push_back(i);
            next.push_back(std::move(q));
          }
        if (next.size() > kLimit) throw InputError("export-strips: more than 100,000 action variants");
      }
      parts = std::move(next);
    }
    for (Partial& p : parts) {
      Variant v{a, std::move(p.pre), {}, {}};
      std::set<int> add(ga.eff.add.begin(), ga.eff.add.end()), del(ga.eff.del.begin(), ga.eff.del.end());
      for (size_t i : p.fired) {
        add.insert(ga.cond_eff[i].eff.add.begin(), ga.cond_eff[i].eff.add.end());
        del.insert(ga.cond_eff[i].eff.del.begin(), ga.cond_eff[i].eff.del.end());
      }
      v.add.assign(add.begin(), add.end());
      for (int b : del)
        if (!add.count(b)) v.del.push_back(b);
      variants.push_back(std::move(v));
      ++variant_count[static_cast<size_t>(a)];
      if (variants.size() > kLimit) throw InputError("export-strips: more than 100,000 actions");
    }
  }

  // ---- atoms: names, and complements of those read negated
  std::set<int> negated;
  for (const Variant& v : variants)
    for (int l : v.pre)
      if (l & 1) negated.insert(l >> 1);
  for (const Clause& c : goal_dnf)
    for (int l : c)
      if (l & 1) negated.insert(l >> 1);
  std::set<std::string> predicate_names;
  for (const auto& p : dom.predicates) predicate_names.insert(p.name);
  std::map<int, std::string> complement_pred;  // predicate id -> its complement's name
  for (int b : negated) {
    const int pred = task.atom_info(b).first;
    if (!complement_pred.count(pred))
      complement_pred[pred] = unique_name("not-" + dom.predicates[static_cast<size_t>(pred)].name, predicate_names);
  }
  auto atom_text = [&](int bit, bool complement) {
    const auto& [pred, args] = task.atom_info(bit);
    std::string s = "(" + (complement ? complement_pred.at(pred) : dom.predicates[static_cast<size_t>(pred)].name);
    for (pddl::ObjectId o : args) s += " " + task.object_name(o);
    return s + ")";
  };
  auto literal_text = [&](int l) { return atom_text(l >> 1, (l & 1) != 0); };

  StripsExport out;
  out.cost_scale = scale;
  std::string goal_reached;
  if (goal_dnf.size() > 1) goal_reached = unique_name("goal-reached", predicate_names);

  // ---- domain
  std::string d = fmt::format("; {} grounded to plain STRIPS by clips export-strips ({} actions; costs x {})\n",
                              dom.name, variants.size(), scale);
  d += fmt::format("(define (domain {}-grounded)\n  (:requirements :strips :action-costs)\n  (:constants", dom.name);
  for (pddl::ObjectId o = 0; o < task.num_objects(); ++o) d += " " + task.object_name(o);
  d += ")\n  (:predicates";
  std::set<int> used_preds;
  for (int b = 0; b < task.num_atoms(); ++b) used_preds.insert(task.atom_info(b).first);
  auto declare = [&](const std::string& name, size_t arity) {
    d += "\n    (" + name;
    for (size_t i = 0; i < arity; ++i) d += fmt::format(" ?x{}", i);
    d += ")";
  };
  for (int pred : used_preds) declare(dom.predicates[static_cast<size_t>(pred)].name, dom.predicates[static_cast<size_t>(pred)].arg_types.size());
  for (const auto& [pred, name] : complement_pred) declare(name, dom.predicates[static_cast<size_t>(pred)].arg_types.size());
  if (!goal_reached.empty()) declare(goal_reached, 0);
  d += ")\n  (:functions (total-cost) - number)\n";

  std::set<std::string> action_names;
  std::vector<int> variant_index(static_cast<size_t>(na), 0);
  for (const Variant& v : variants) {
    const auto& ga = task.action(v.action);
    std::string base = dom.actions[ga.schema].name;
    for (pddl::ObjectId o : ga.args) base += "_" + task.object_name(o);
    if (variant_count[static_cast<size_t>(v.action)] > 1)
      base += "__" + std::to_string(++variant_index[static_cast<size_t>(v.action)]);
    const std::string name = unique_name(base, action_names);
    out.original_actions[name] = task.action_name(v.action);
    d += "  (:action " + name + "\n   :parameters ()\n   :precondition (and";
    for (int l : v.pre) d += " " + literal_text(l);
    d += ")\n   :effect (and";
    for (int b : v.add) {
      d += " " + atom_text(b, false);
      if (negated.count(b)) d += " (not " + atom_text(b, true) + ")";
    }
    for (int b : v.del) {
      d += " (not " + atom_text(b, false) + ")";
      if (negated.count(b)) d += " " + atom_text(b, true);
    }
    d += fmt::format(" (increase (total-cost) {})))\n",
                     static_cast<long long>(std::llround(cost[static_cast<size_t>(v.action)] * scale)));
  }
  std::string goal_text;
  if (goal_reached.empty()) {
    goal_text = "(and";
    for (int l : goal_dnf.front()) goal_text += " " + literal_text(l);
    goal_text += ")";
  } else {
    for (size_t k = 0; k < goal_dnf.size(); ++k) {
      const std::string name = unique_name(fmt::format("reach-goal-{}", k + 1), action_names);
      out.original_actions[name] = "";
      d += "  (:action " + name + "\n   :parameters ()\n   :precondition (and";
      for (int l : goal_dnf[k]) d += " " + literal_text(l);
      d += ")\n   :effect (and (" + goal_reached + ") (increase (total-cost) 0)))\n";
    }
    goal_text = "(and (" + goal_reached + "))";
  }
  d += ")\n";

  // ---- problem
  std::string p = fmt::format("(define (problem {}-grounded)\n  (:domain {}-grounded)\n  (:init", task.problem().name,
                              dom.name);
  for (int b = 0; b < task.num_atoms(); ++b) {
    const bool on = pddl::get_bit(start.data(), b);
    if (on) p += "\n    " + atom_text(b, false);
    else if (negated.count(b)) p += "\n    " + atom_text(b, true);
  }
  p += "\n    (= (total-cost) 0))\n  (:goal " + goal_text + ")\n  (:metric minimize (total-cost)))\n";

  out.domain = std::move(d);
  out.problem = std::move(p);
  out.goal = goal_text;
  return out;
}

}  // namespace clips::domains
