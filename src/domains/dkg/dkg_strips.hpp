#pragma once
// Compiles one multi-agent Doors-Keys-Gems planning problem (a grounded task, a
// start state, a `has` goal and a cost profile) into an equivalent plain
// STRIPS domain + problem with integer action costs, so that off-the-shelf
// classical planners (Fast Downward, VAL, ...) can solve or check it.
//
// What the compilation does (the domain and its turn-taking, docs/domains.md):
//   * every grid cell that matters is an object c_X_Y; walls disappear into the
//     static movement facts (up-of ?from ?to) etc., which exist only when ?to
//     is an in-grid non-wall cell;
//   * doors sit on cells via (door-at ?d ?c); a locked door blocks entry, and
//     because STRIPS has no negative preconditions the exporter keeps the
//     positive fact (open-cell ?c) for every cell without a locked door;
//   * key/door colour matching becomes static (opens ?k ?d), `forbidden`
//     becomes its positive complement (may-hold ?a ?i), and a frozen agent in
//     the start state simply lacks (unfrozen ?a);
//   * the agents are domain constants and every action type gets one schema
//     per agent (move-up-human, pickup-robot, handover-human-robot, ...), so
//     each schema carries its profile cost as (increase (total-cost) N);
//   * turn-taking: every schema needs (active self) and passes it on to the
//     agents of the static next-turn facts.
// The original's bookkeeping fluents (pickedup-by, unlocked-by, ...) are not
// exported: no precondition reads them, so plan costs are unchanged.
#include <string>
#include <vector>

#include "domains/pack.hpp"
#include "domains/strips.hpp"  // integer_cost_scale
#include "model/spec.hpp"
#include "pddl/state.hpp"
#include "pddl/task.hpp"

namespace clips::domains::dkg {


// Throws InputError for goals that are not a conjunction of (has agent item)
// atoms, for costs that cannot be made integral by a factor up to 1000, for
// the task-costs profile marker, and for tasks that are not mDKG-shaped.
StripsExport export_strips(const pddl::Task& task, const pddl::State& start, const std::string& goal,
                           const model::CostProfile& costs);

// Maps one exported ground action back to the original domain's action, e.g.
// "(move-up-human c_5_3 c_5_2)" -> "(up human)",
// "(handover-robot-human key1 c_5_4 c_5_3)" -> "(handover robot human key1)".
// Throws InputError for names the exporter never produces.
std::string to_original_action(const std::string& exported_action);

}  // namespace clips::domains::dkg
