#pragma once
// A lifted command.
//
// A command is what the speaker might ask for: an ordered list of actions with
// pronouns for the two agents and variables for every other object, plus the
// qualifying predicates of the commanded objects, e.g.
//   (pickup you ?key1) (handover you me ?key1) where (iscolor ?key1 red) (iscolor ?key1 red)
// Two commands are the same iff their actions, predicates and typed variables
// are equal in order (the reference's de-duplication); the ground binding a
// command was lifted from is carried along for reference but not compared.
#include <string>
#include <vector>

#include "commands/language_config.hpp"
#include "commands/salient.hpp"
#include "commands/term.hpp"

namespace clips::commands {

struct Variable {
  std::string name;  // without '?': "key1" (mDKG) or "Plate1", "Fixture1" (VH)
  std::string type;  // PDDL type of the object it replaced: "key", "item", "fixture"
  bool operator==(const Variable&) const = default;
};

struct Binding {
  std::string variable;  // without '?'
  std::string object;
  bool operator==(const Binding&) const = default;
};

struct Command {
  std::vector<Term> actions;        // lifted; variables appear as "?key1"
  std::vector<Term> predicates;     // lifted; in action order, repeats kept
  std::vector<Variable> variables;  // in order of first appearance
  std::vector<Binding> binding;     // variable -> ground object it was lifted from
  PrintedForm printed_form = PrintedForm::WhereClause;
  std::string qualifier;  // predicate name the VH printed form drops, e.g. "itemtype"
  // The actions as the language model reads them when the config prints
  // agents and focal objects only; empty: `actions`.
  std::vector<Term> printed_actions;
  // The places it names whose number people say (LanguageConfig::
  // numbered_names): llm_form marks their numbers ("shelf#3").
  std::vector<std::string> numbered;

  // Actions, then " where " and the predicates if any; variables as "?key1".
  std::string display_form() const;
  // The text placed after "Input: " in prompts.
  std::string llm_form() const;
  // PDDL goal condition. Throws std::invalid_argument
  // if an action has no goal atoms in the config.
  std::string to_goal_formula(const LanguageConfig& config) const;

  bool operator==(const Command& other) const {
    return actions == other.actions && predicates == other.predicates && variables == other.variables;
  }
};

// Replaces agent names by pronouns and every other constant by a variable
//, for salient actions already chosen for one command.
Command lift_command(const std::vector<SalientAction>& subset, const LanguageConfig& config,
                     const TypeLookup& type_of);

// Two commands as one (several utterances in a plan): union of actions, of predicates and of variables, first command first.
Command merge_commands(const Command& first, const Command& second);

// Substitutes bound variables ("?key1" -> object); other arguments are kept.
Term substitute(const Term& term, const std::vector<Binding>& binding);
std::vector<Term> substitute(const std::vector<Term>& terms, const std::vector<Binding>& binding);

// Maps pronouns back to agent names (you -> robot, me -> human).
Term to_agent_names(const Term& term, const LanguageConfig& config);

}  // namespace clips::commands
