#pragma once
// Salient actions: the actions of a rollout that a
// command may mention, each with its acting agent, its focal object and the
// focal object's qualifying predicate, e.g. (iscolor key2 red).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "commands/language_config.hpp"
#include "commands/term.hpp"

namespace clips::commands {

struct SalientAction {
  Term action;                  // ground, with agent names, e.g. (pickup robot key2)
  std::string agent;            // e.g. "robot"
  std::string focal;            // e.g. "key2"
  std::vector<Term> predicates; // e.g. {(iscolor key2 red)}; empty if the object has none
};

// The qualifying predicate of an object in the scoring state, if any.
// The qualifier terms of an object, in the config's qualifier order (empty: none).
using QualifierLookup = std::function<std::vector<Term>(const std::string& object)>;
// The PDDL type of an object ("key", "door", "item", "fixture", ...).
using TypeLookup = std::function<std::string(const std::string& object)>;

// Salient actions of `actions` in order (non-salient actions are skipped).
// An empty `qualifier_of` attaches no predicates.
// Throws std::invalid_argument if a salient action lacks its agent or focal argument.
std::vector<SalientAction> extract_salient(const std::vector<Term>& actions, const LanguageConfig& config,
                                           const QualifierLookup& qualifier_of);

// A lookup over a list of facts: for each of config.qualifiers(), the first fact of that name whose
// object argument is the object, e.g. from {(iscolor key2 red), (iscolor door1 blue)}.
QualifierLookup qualifier_lookup_from_facts(std::vector<Term> facts, const LanguageConfig& config);

}  // namespace clips::commands
