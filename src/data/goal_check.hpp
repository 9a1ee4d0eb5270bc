#pragma once
// Goals that can never hold. A candidate goal no state can satisfy makes
// inference plan for the impossible (minutes of search) and still gets
// posterior mass; such a goal is a mistake in the data, refused at load.
#include <string>

#include "pddl/task.hpp"

namespace clips::data {

// Why `goal` holds in no state reachable from `from`, or "" when it may hold.
// Sound but not complete: a goal is refused only when every disjunct of its
// DNF (over atoms; comparisons count as satisfiable) needs an atom both true
// and false, an atom that no action can make true (delete relaxation from
// `from`), or false an atom that is true in `from` and that no action
// deletes; or when it folds to false. A DNF of more than 4096 clauses is
// given the benefit of the doubt.
std::string why_goal_never_holds(const pddl::Task& task, const pddl::CompiledCondition& goal, const pddl::State& from);

}  // namespace clips::data
