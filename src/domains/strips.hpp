#pragma once
// A grounded task compiled to plain STRIPS PDDL (domain + problem) with
// integer action costs, for any pack: an outside classical planner such as
// Fast Downward can then check clips' optimal plans. (Doors-Keys-Gems keeps
// its own compilation, dkg/dkg_strips.hpp, which also turns its numeric grid
// into atoms.)
//
// What is exported:
//   * every dynamic ground atom as an atom over the domain's constants (the
//     problem's objects), e.g. (at human rack); static facts are folded into
//     the actions, as grounding did;
//   * every ground action as a parameterless action whose name is its schema
//     and arguments joined by '_' (made unique by a suffix where needed),
//     costing its profile cost times `cost_scale` (the least integer factor
//     making every cost integral);
//   * negative literals through complement atoms: for an atom p that occurs
//     negated in a precondition, an effect condition or the goal, (not-p ...)
//     holds exactly when p does not (set in the initial state, kept by every
//     effect on p);
//   * a precondition that is not a conjunction of literals (a disjunction, a
//     negated conjunction) as one action per clause of its DNF, and an action
//     with conditional effects as one action per combination of its effects
//     firing or not (their conditions and negations in DNF): every variant has
//     the original's cost and, where applicable, the original's effect;
//   * a disjunctive goal through an atom (goal-reached) and one zero-cost
//     action per DNF clause.
// Not exported (InputError): numeric fluents and comparisons, and tasks whose
// compilation exceeds 100,000 actions or clauses.
#include <map>
#include <string>
#include <vector>

#include "domains/pack.hpp"
#include "model/spec.hpp"
#include "pddl/state.hpp"
#include "pddl/task.hpp"

namespace clips::domains {

// StripsExport::original_actions maps every exported action back, e.g.
// "move_human_rack_bench" -> "(move human rack bench)"; the goal actions map
// to "".
StripsExport export_grounded_strips(const pddl::Task& task, const pddl::State& start, const std::string& goal,
                                    const model::CostProfile& costs);

// The smallest integer k in 1..max_scale with every cost * k integral (within a
// relative tolerance, so 0.6 * 5 = 3.0000000000000004 counts); throws
// InputError if there is none or a cost is negative or not finite.
int integer_cost_scale(const std::vector<double>& costs, int max_scale = 1000);

}  // namespace clips::domains
