#pragma once
// A reading of an instruction in parts a front end can say in words. The
// engine names each reading by its command's display form,
//   (pickup you ?key1) (handover you me ?key1) where (iscolor ?key1 red)
// and this splits it into steps, each an agent, an action and its objects:
//   [{"agent": "robot", "action": "pickup", "verb": "pick up",
//     "objects": [{"name": "?key1", "noun": "key", "qualities": ["red"]}]},
//    {"agent": "robot", "action": "handover", "verb": "hand over",
//     "objects": [{"name": "human", "noun": "human", "qualities": []}, {"name": "?key1", ...}]}]
// so that the play page says "robot: pick up the red key, hand it over to
// human" while the PDDL form stays one click away. Pronouns become the
// pack's agents; a variable's qualities are its qualifier facts in the where
// clause, "from" the place a location fact puts it at, "to" a destination
// ((to ?compost1 border)); a named object's qualities are the pack's
// qualifier values. A variable that is not the action's focal object and
// has neither quality nor place is left out, as people leave it unsaid (the
// room of a hand-over). The verb is the action's name as words (WordNet splits
// run-together names: "pickup" is "pick up"). Nothing here knows a domain.
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "domains/pack.hpp"
#include "pddl/task.hpp"

namespace clips::serve {

class CommandWords {
 public:
  CommandWords(std::shared_ptr<const pddl::Task> task, const domains::Pack& pack);

  // The steps of a command's display form; empty for text that is not a
  // command of this domain ("(no command: ...)"). `goal_statement`: the
  // command states a goal (engine::Reading::Command::goal), whose own
  // (make me ?goal1) step is left out: the goal is said by its label.
  nlohmann::json steps(const std::string& display_form, bool goal_statement) const;

 private:
  std::string verb(const std::string& action) const;

  std::shared_ptr<const pddl::Task> task_;
  commands::LanguageConfig config_;
  domains::QualifierOf qualifier_;
  mutable std::map<std::string, std::string> verbs_;  // action name -> words (WordNet lookups are slow)
};

}  // namespace clips::serve
