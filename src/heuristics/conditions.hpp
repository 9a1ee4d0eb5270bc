#pragma once
// Reading compiled conditions for the relaxation heuristics: the atoms of a
// conjunction, a goal's DNF, and rows packed as CSR arrays.
#include <vector>

#include "pddl/task.hpp"

namespace clips::heuristics {

// The atoms of a condition's top-level conjunction: positive ones into
// `pos`, and, when `neg` is given, those it requires false.
void conjuncts(const pddl::Task& t, pddl::CondId c, std::vector<int>& pos, std::vector<int>* neg = nullptr);

// DNF of a compiled condition over positive atoms (anything else counts as
// true). `sorted`: clauses sorted and deduplicated as they are built (an
// existential goal over variables no atom reads repeats every clause); else
// clauses in the condition's order, as h_max reads them. More than 4096
// clauses: {{}} (always satisfied, so an estimate of 0).
std::vector<std::vector<int>> goal_dnf(const pddl::CompiledCondition& g, bool sorted);

// The same DNF (sorted) with negative literals kept: (not b) as -(b + 1).
std::vector<std::vector<int>> goal_dnf_literals(const pddl::CompiledCondition& g);

// A derived predicate's rule read as relaxed operators: the DNF of its body
// over positive atoms (other literals dropped), or, above a few clauses,
// the positive atoms of its top-level conjunction as one clause. Each clause
// with the rule's head is a zero-cost operator of the delete relaxation:
// wherever the rule fires, one clause's atoms hold, so the relaxation stays
// a relaxation (h_max, LM-cut admissible).
std::vector<std::vector<int>> axiom_clauses(const pddl::Task& t, pddl::CondId body);

// Sorted, duplicates removed: one clause; every clause, then the clauses.
void normalise(std::vector<int>& clause);
void normalise_all(std::vector<std::vector<int>>& clauses);

// Rows as CSR: row i is flat[begin[i] .. begin[i + 1]).
void to_csr(const std::vector<std::vector<int>>& rows, std::vector<int>& begin, std::vector<int>& flat);

}  // namespace clips::heuristics
