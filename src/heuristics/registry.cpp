#include "heuristics/registry.hpp"

#include "heuristics/basic.hpp"
#include "heuristics/lmcut.hpp"

namespace clips::heuristics {

util::Choices<HeuristicMaker>& generic_heuristic_choices() {
  static util::Choices<HeuristicMaker> table(
      "heuristic",
      {
          {[](const pddl::Task&) { return std::make_unique<LmCutHeuristic>(); }, "lmcut",
           "LM-cut, turn-aware (admissible)", {}},
          {[](const pddl::Task&) { return std::make_unique<HMaxHeuristic>(); }, "hmax", "h_max (admissible)", {}},
          {[](const pddl::Task&) { return std::make_unique<BlindHeuristic>(); }, "blind", "0 everywhere", {}},
          {[](const pddl::Task&) { return std::make_unique<FFHeuristic>(/*turns=*/true); }, "hff",
           "the FF heuristic, counting the agents' turns (not admissible)", {}},
          {[](const pddl::Task&) { return std::make_unique<FFHeuristic>(/*turns=*/true, /*negations=*/false); },
           "hff-noneg", "hff without negative preconditions", {}},
          {[](const pddl::Task&) { return std::make_unique<FFHeuristic>(/*turns=*/false); }, "hff-plain",
           "the FF heuristic without turns", {}},
          {[](const pddl::Task&) { return std::make_unique<LmCutHeuristic>(/*turns=*/true, /*negations=*/false); },
           "lmcut-noneg", "lmcut without negative preconditions", {}},
      });
  return table;
}

}  // namespace clips::heuristics
