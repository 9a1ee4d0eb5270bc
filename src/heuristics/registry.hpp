#pragma once
// The one name table of the heuristics every domain pack offers
// (util/choices.hpp): a name, a line of help and how to make one. A pack adds
// its own table in front (domains::Pack::own_heuristics); `--heuristic`,
// pack.json's heuristic fields and the errors for an unknown name read both.
#include <functional>
#include <memory>

#include "heuristics/heuristic.hpp"
#include "util/choices.hpp"

namespace clips::heuristics {

using HeuristicMaker = std::function<std::unique_ptr<Heuristic>(const pddl::Task&)>;

util::Choices<HeuristicMaker>& generic_heuristic_choices();

}  // namespace clips::heuristics
