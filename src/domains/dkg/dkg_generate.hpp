#pragma once
// Random Doors-Keys-Gems problems for `clips generate` (the mDKG pack's
// Pack::generate_problem).
//
// A map is made by recursive division: a wall is drawn across a room (on an
// even row or column) with one gap (on an odd one, so that no later wall can
// block it), splitting the room in two; `doors` such walls get a locked door
// in their gap, and sometimes one more wall keeps an open gap. Every gap is
// then a chokepoint. The human, the robot and all keys start in the largest
// room that no locked door closes off (the home room); the gems are spread
// over the rooms behind doors, so every gem needs at least one door opened,
// and every door must stand between the human and some gem. Door colours are
// drawn from the paper's key colours (red, yellow, blue) and keys are
// coloured so that each gem's doors can be opened with the keys there are
// (keys are used up). Objects are numbered in row-major scan order and gems
// coloured by number (gem1 red, gem2 yellow, gem3 blue, gem4 green, gem5 red
// again, ...), as in the paper's maps. Solvability by search is left to
// the caller.
#include <optional>

#include "domains/pack.hpp"
#include "util/rng.hpp"

namespace clips::domains::dkg {

// Throws InputError when no map can ever have these counts: sizes outside
// 3..40, no gem or more than 64, locked doors without any key, more objects
// than cells, or more than the 128 objects the grid heuristics track.
void check_dkg_generate_params(const GenerateParams& params);

// One draw; nullopt when it gave no acceptable layout (the caller draws
// again). Calls check_dkg_generate_params first.
std::optional<GeneratedProblem> generate_dkg_problem(const GenerateParams& params, util::Rng& rng);

}  // namespace clips::domains::dkg
