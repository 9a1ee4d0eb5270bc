#pragma once
// The embedded language model's view of a domain (lm::DomainDescription, see
// lm/domain_corpus.hpp), read from the parsed PDDL and the domain's command
// model, for a domain that ships no hand-written corpus. The inference code
// passes the result to lm::embedded_options_for_domain().
#include <string>
#include <vector>

#include "commands/language_config.hpp"
#include "lm/domain_corpus.hpp"
#include "pddl/ast.hpp"

namespace clips::language {

// Action schemas with their parameter types, the type hierarchy, the
// problem's objects and the init facts of the qualifier predicates, and the
// command grammar of `config` (salient actions, agents, pronouns).
// `qualifier_predicates`: the two-argument predicates that qualify objects
// (e.g. {"issize", "ismaterial"}); empty means config.qualifier alone.
lm::DomainDescription describe_for_language_model(const pddl::Domain& domain, const pddl::Problem& problem,
                                                  const commands::LanguageConfig& config,
                                                  const std::vector<std::string>& qualifier_predicates = {});

// The names of the problem's objects that commands name by their number
// (commands::numbered_names over the objects commands do not lift: places
// and fixtures, not the things a salient action is about, nor agents).
std::vector<std::string> numbered_place_names(const pddl::Domain& domain, const pddl::Problem& problem,
                                              const commands::LanguageConfig& config);

}  // namespace clips::language
