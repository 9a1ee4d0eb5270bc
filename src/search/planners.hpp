#pragma once
// The planners `clips plan --planner` runs, as a name table (util/choices.hpp):
// A* (astar.hpp) searches to the goal once; RTAA* (rtaa.hpp) acts, one
// lookahead search before each executed action.
#include "util/choices.hpp"

namespace clips::search {

enum class Planner { AStar, Rtaa };
util::Choices<Planner>& planner_choices();

}  // namespace clips::search
