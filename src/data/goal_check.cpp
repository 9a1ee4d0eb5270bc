#include "data/goal_check.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace clips::data {

namespace {

using CNode = pddl::Task::CNode;

constexpr size_t kMaxClauses = 4096;

// A literal: bit b true is b, false is ~b (negative).
using Clause = std::vector<int>;

// The DNF of a goal over literals; nullopt when it grows past kMaxClauses.
std::optional<std::vector<Clause>> dnf(const pddl::CompiledCondition& g, pddl::CondId c) {
  const CNode& n = g.cnode(c);
  switch (n.op) {
    case CNode::False: return std::vector<Clause>{};
    case CNode::Atom: return std::vector<Clause>{{n.a}};
    case CNode::NotAtom: return std::vector<Clause>{{~n.a}};
    case CNode::Or: {
      std::vector<Clause> out;
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i]);
        if (!k) return std::nullopt;
        out.insert(out.end(), k->begin(), k->end());
        if (out.size() > kMaxClauses) return std::nullopt;
      }
      return out;
    }
    case CNode::And: {
      std::vector<Clause> acc{{}};
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i]);
        if (!k) return std::nullopt;
        std::vector<Clause> next;
        for (const Clause& a : acc)
          for (const Clause& b : *k) {
            if (next.size() >= kMaxClauses) return std::nullopt;
            Clause m = a;
            m.insert(m.end(), b.begin(), b.end());
            next.push_back(std::move(m));
          }
        acc = std::move(next);
      }
      return acc;
    }
    default: return std::vector<Clause>{{}};  // True, comparisons, nested negations: may hold
  }
}

// The positive atoms of a precondition's top-level conjunction.
void positive_conjuncts(const pddl::Task& t, pddl::CondId c, std::vector<int>& out) {
  const CNode& n = t.cnode(c);
  if (n.op == CNode::Atom) out.push_back(n.a);
  if (n.op == CNode::And)
    for (int i = 0; i < n.b; ++i) positive_conjuncts(t, t.ckids()[n.a + i], out);
}

bool bit_of(const pddl::State& s, int bit) { return (s.data()[bit / 64] >> (bit % 64)) & 1; }

}  // namespace

std::string why_goal_never_holds(const pddl::Task& task, const pddl::CompiledCondition& goal, const pddl::State& from) {
  if (goal.is_const_false()) return "it is false in every state (it contradicts itself or the problem's fixed facts)";
  const auto clauses = dnf(goal, goal.root());
  if (!clauses) return "";
  // Delete relaxation: atoms some sequence of actions could make true, and
  // atoms some action that could be taken deletes.
  const int atoms = task.num_atoms();
  std::vector<char> reached(static_cast<size_t>(atoms)), deletable(static_cast<size_t>(atoms));
  for (int b = 0; b < atoms; ++b) reached[static_cast<size_t>(b)] = bit_of(from, b);
  std::vector<std::vector<int>> pre(static_cast<size_t>(task.num_actions()));
  for (pddl::ActionId a = 0; a < task.num_actions(); ++a) positive_conjuncts(task, task.action(a).pre, pre[a]);
  std::vector<char> used(static_cast<size_t>(task.num_actions()));
  for (bool changed = true; changed;) {
    changed = false;
    for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
      if (used[a] || !std::all_of(pre[a].begin(), pre[a].end(), [&](int b) { return reached[b] != 0; })) continue;
      used[a] = 1;
      changed = true;
      const pddl::GroundAction& ga = task.action(a);
      auto take = [&](const pddl::EffectList& e) {
        for (int b : e.add) reached[static_cast<size_t>(b)] = 1;
        for (int b : e.del) deletable[static_cast<size_t>(b)] = 1;
      };
      take(ga.eff);
      for (const auto& ce : ga.cond_eff) take(ce.eff);
    }
  }
  std::string why;
  for (const Clause& clause : *clauses) {
    std::string blocked;
    for (int lit : clause) {
      const int bit = lit >= 0 ? lit : ~lit;
      if (std::find(clause.begin(), clause.end(), ~lit) != clause.end()) {
        blocked = task.atom_str(bit) + " must be both true and false";
      } else if (lit >= 0 && !reached[static_cast<size_t>(bit)]) {
        blocked = "no sequence of actions makes " + task.atom_str(bit) + " true";
      } else if (lit < 0 && bit_of(from, bit) && !deletable[static_cast<size_t>(bit)]) {
        blocked = task.atom_str(bit) + " is true and no action makes it false";
      }
      if (!blocked.empty()) break;
    }
    if (blocked.empty()) return "";  // this way of satisfying it may work
    if (why.empty()) why = blocked;
  }
  if (clauses->empty()) return "it is false in every state";
  return clauses->size() == 1 ? why : "no way of satisfying it can hold (the first: " + why + ")";
}

}  // namespace clips::data
