#include "heuristics/conditions.hpp"

#include <algorithm>

namespace clips::heuristics {

using CNode = pddl::Task::CNode;

namespace {

constexpr size_t kMaxClauses = 4096;

// `G` reads a pool: a CompiledCondition, or a Task (its own pool).
// `negative`: literals (not b) as -(b + 1); else they count as true.
template <class G>
std::vector<std::vector<int>> dnf(const G& g, pddl::CondId c, bool norm, size_t max_clauses = kMaxClauses,
                                  bool negative = false) {
  const CNode& n = g.cnode(c);
  switch (n.op) {
    case CNode::False: return {};
    case CNode::Atom: return {{n.a}};
    case CNode::NotAtom:
      if (negative) return {{-(n.a + 1)}};
      return {{}};
    case CNode::Or: {
      std::vector<std::vector<int>> out;
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i], norm, max_clauses, negative);
        out.insert(out.end(), k.begin(), k.end());
        if (norm && out.size() > max_clauses) normalise_all(out);
        // (Goals keep their disjunctions whole, as they always have.)
        if (max_clauses < kMaxClauses && out.size() > max_clauses) return {{}};
      }
      if (norm) normalise_all(out);
      return out;
    }
    case CNode::And: {
      std::vector<std::vector<int>> acc{{}};
      for (int i = 0; i < n.b; ++i) {
        auto k = dnf(g, g.ckids()[n.a + i], norm, max_clauses, negative);
        std::vector<std::vector<int>> next;
        for (auto& a : acc)
          for (auto& b : k) {
            auto m = a;
            m.insert(m.end(), b.begin(), b.end());
            next.push_back(std::move(m));
          }
        acc = std::move(next);
        if (norm) normalise_all(acc);
        if (acc.size() > max_clauses) return {{}};  // too large: give up (0 is admissible)
      }
      return acc;
    }
    default: return {{}};
  }
}

}  // namespace

void normalise(std::vector<int>& clause) {
  std::sort(clause.begin(), clause.end());
  clause.erase(std::unique(clause.begin(), clause.end()), clause.end());
}

void normalise_all(std::vector<std::vector<int>>& clauses) {
  for (auto& c : clauses) normalise(c);
  std::sort(clauses.begin(), clauses.end());
  clauses.erase(std::unique(clauses.begin(), clauses.end()), clauses.end());
}

void conjuncts(const pddl::Task& t, pddl::CondId c, std::vector<int>& pos, std::vector<int>* neg) {
  const CNode& n = t.cnode(c);
  if (n.op == CNode::Atom) pos.push_back(n.a);
  if (n.op == CNode::NotAtom && neg) neg->push_back(n.a);
  if (n.op == CNode::And)
    for (int i = 0; i < n.b; ++i) conjuncts(t, t.ckids()[n.a + i], pos, neg);
}

void to_csr(const std::vector<std::vector<int>>& rows, std::vector<int>& begin, std::vector<int>& flat) {
  begin.assign(rows.size() + 1, 0);
  flat.clear();
  for (size_t i = 0; i < rows.size(); ++i) {
    flat.insert(flat.end(), rows[i].begin(), rows[i].end());
    begin[i + 1] = static_cast<int>(flat.size());
  }
}

std::vector<std::vector<int>> goal_dnf(const pddl::CompiledCondition& g, bool sorted) {
  return dnf(g, g.root(), sorted);
}

std::vector<std::vector<int>> goal_dnf_literals(const pddl::CompiledCondition& g) {
  return dnf(g, g.root(), true, kMaxClauses, true);
}

std::vector<std::vector<int>> axiom_clauses(const pddl::Task& t, pddl::CondId body) {
  constexpr size_t kMaxAxiomClauses = 16;
  auto clauses = dnf(t, body, true, kMaxAxiomClauses);
  if (clauses.size() == 1 && clauses[0].empty()) {
    // Too many clauses (or none needs an atom): the top-level conjunction's atoms.
    std::vector<int> pos;
    conjuncts(t, body, pos);
    normalise(pos);
    return {pos};
  }
  return clauses;
}

}  // namespace clips::heuristics
