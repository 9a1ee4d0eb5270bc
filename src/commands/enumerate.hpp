#pragma once
// Command enumeration: every subset of the
// salient actions of size 1..K in lexicographic order, filtered by the
// exclusion rules, lifted, de-duplicated keeping first occurrences. Each
// distinct lifted command then has probability 1/|C|.
#include <cstddef>
#include <vector>

#include "commands/command.hpp"
#include "commands/language_config.hpp"
#include "commands/salient.hpp"
#include "commands/term.hpp"

namespace clips::commands {

// The subsets that pass the speaker, action-type, chain and qualifier rules,
// as increasing indices into `salient`, in enumeration order (before lifting).
std::vector<std::vector<std::size_t>> select_command_subsets(const std::vector<SalientAction>& salient,
                                                             const LanguageConfig& config);

// Distinct lifted commands of the salient actions of one rollout.
std::vector<Command> enumerate_commands(const std::vector<SalientAction>& salient, const LanguageConfig& config,
                                        const TypeLookup& type_of);

// Literal listener: the caller lists the candidate
// ground actions (e.g. every pickup(robot,k), handover(robot,human,k) and
// same-colour unlock(robot,k,d), or every placed VH grab); they get their
// qualifiers and go through the same enumeration.
std::vector<Command> enumerate_literal_candidates(const std::vector<Term>& candidate_actions,
                                                  const LanguageConfig& config,
                                                  const QualifierLookup& qualifier_of,
                                                  const TypeLookup& type_of);

// The command prior: 1/|C| each (multiplicity of ground subsets is ignored).
std::vector<double> uniform_command_weights(std::size_t command_count);

}  // namespace clips::commands
