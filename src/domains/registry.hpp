#pragma once
// Domain hooks behind one interface: which heuristics a domain offers, its
// default heuristic and cost profiles. A new domain adds a case here and its
// own files in this folder.
#include <memory>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "heuristics/heuristic.hpp"

namespace clips::domains {

// Names accepted by make_heuristic for a domain kind, default first.
std::vector<std::string> heuristic_names(data::DomainKind kind);
// The admissible default used for optimal planning.
std::string default_admissible_heuristic(data::DomainKind kind);
// The heuristic the human model plans with (inference and assistance):
// the paper's DoorsKeysMSTHeuristic in mDKG.
std::string model_heuristic(data::DomainKind kind);
std::unique_ptr<heuristics::Heuristic> make_heuristic(const std::string& name, const pddl::Task& task,
                                                      data::DomainKind kind);
// Cost profile by user-facing number/name: mDKG "1".."4" (C1..C4); "unit";
// "task" (the domain's own action costs).
model::CostProfile cost_profile(data::DomainKind kind, const std::string& which);

}  // namespace clips::domains
