#include "domains/registry.hpp"

#include "domains/dkg_heuristic.hpp"
#include "heuristics/basic.hpp"

namespace clips::domains {

std::vector<std::string> heuristic_names(data::DomainKind kind) {
  if (kind == data::DomainKind::DoorsKeysGems) return {"dkg-dist", "dkg-mst", "hmax", "blind"};
  return {"hmax", "blind"};
}

std::string default_admissible_heuristic(data::DomainKind kind) {
  // The mDKG MST heuristic of the paper is not admissible; the distance bound is.
  return kind == data::DomainKind::DoorsKeysGems ? "dkg-dist" : "hmax";
}

std::string model_heuristic(data::DomainKind kind) {
  return kind == data::DomainKind::DoorsKeysGems ? "dkg-mst" : "hmax";
}

std::unique_ptr<heuristics::Heuristic> make_heuristic(const std::string& name, const pddl::Task& task,
                                                      data::DomainKind kind) {
  (void)task;
  if (kind == data::DomainKind::DoorsKeysGems) {
    if (name == "dkg-mst") return std::make_unique<DkgMstHeuristic>();
    if (name == "dkg-dist") return std::make_unique<DkgDistanceHeuristic>();
  }
  if (name == "blind") return std::make_unique<heuristics::BlindHeuristic>();
  if (name == "hmax") return std::make_unique<heuristics::HMaxHeuristic>();
  std::string known;
  for (auto& n : heuristic_names(kind)) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown heuristic '" + name + "' for " + data::to_string(kind) + " (known: " + known + ")");
}

model::CostProfile cost_profile(data::DomainKind kind, const std::string& which) {
  if (which == "unit") return model::unit_profile();
  if (which == "task") return model::task_costs_profile();
  if (kind == data::DomainKind::DoorsKeysGems) {
    std::string w = which;
    if (!w.empty() && (w[0] == 'C' || w[0] == 'c')) w = w.substr(1);
    if (w == "1" || w == "2" || w == "3" || w == "4") return model::dkg_profile(std::stoi(w));
    throw InputError("--costs must be 1..4 (C1..C4), 'unit' or 'task' for doors-keys-gems, got '" + which + "'");
  }
  if (which.empty() || which == "1") return model::unit_profile();
  throw InputError("--costs must be 'unit' or 'task' for this domain, got '" + which + "'");
}

}  // namespace clips::domains
