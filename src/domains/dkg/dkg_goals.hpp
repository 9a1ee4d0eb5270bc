#pragma once
// Goal facts that Doors-Keys-Gems can never make true together: unlocking a
// door consumes the key (it leaves the grid and nobody holds it again), so a
// conjunction asking that some agent *has* key k and that k *unlocked* a door
// is unsatisfiable. The literal listener's commands often chain "pick up k,
// unlock with k"; recognising them saves a search that can only fail.
#include <string>

namespace clips::domains::dkg {

// True when `goal` (a conjunction, possibly under exists) requires facts that
// exclude each other: a key both held and used; one item held by two agents;
// one door unlocked with two keys; one key used on two doors. Terms count as
// different objects when they are different constants or variables declared
// unequal. Anything else (disjunctions, ...) is never called unsatisfiable.
bool dkg_goal_unsatisfiable(const std::string& goal);

}  // namespace clips::domains::dkg
