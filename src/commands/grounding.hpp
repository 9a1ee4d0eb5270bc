#pragma once
// From lifted commands back to objects: the naive listener's
// groundings, and the focal objects that a command or a plan commits to.
#include <map>
#include <string>
#include <vector>

#include "commands/command.hpp"
#include "commands/language_config.hpp"
#include "commands/term.hpp"

namespace clips::commands {

struct GroundCommand {
  std::vector<Term> actions;     // pronouns kept, as in the lifted command
  std::vector<Term> predicates;
  std::vector<Binding> binding;  // in the command's variable order
};

// Every assignment of pairwise distinct objects of the right types to the
// command's variables under which all its predicates are among `facts`;
// variables take objects in the order listed, the first variable varying
// slowest. Groundings equal as sets of actions and of predicates are kept
// once (the first). A command without variables is its own single grounding.
std::vector<GroundCommand> naive_groundings(const Command& command,
                                            const std::map<std::string, std::vector<std::string>>& objects_by_type,
                                            const std::vector<Term>& facts);

// The focal argument of each salient action, without repeats, in order.
std::vector<std::string> focal_objects(const std::vector<Term>& actions, const LanguageConfig& config);

// Efficient listener: the objects bound to the command's focal
// variables when each command action (pronouns mapped back) is unified with
// each action of a plan, and a focal object the command names (a place) when
// an action of it unifies; without repeats, in order found.
std::vector<std::string> match_focal_objects(const Command& command, const std::vector<Term>& plan,
                                             const LanguageConfig& config);

}  // namespace clips::commands
