#pragma once
// The paper domains' language settings (clips-spec.md 7.4), written out by
// hand for the command tests. The shipped packs define them in data; the pack
// tests check that the packs' settings equal these.
#include "commands/language_config.hpp"

namespace clips::commands {

inline LanguageConfig doors_keys_gems_language() {
  LanguageConfig c;
  c.domain = "doors-keys-gems";
  c.salient_actions = {{"pickup", 1, 2}, {"handover", 1, 3}, {"unlock", 1, 3}};
  c.qualifier = "iscolor";
  c.qualifier_object_arg = 1;
  c.speaker = "human";
  c.listener = "robot";
  c.max_command_actions = 3;
  c.max_action_types = 2;
  c.max_qualifier_values_per_action_type = 1;
  c.variable_naming = VariableNaming::ObjectType;
  c.printed_form = PrintedForm::WhereClause;
  c.paper_speaker_actions = SpeakerActionRule::ExcludeSpeakerOnlyCommands;
  c.paper_exclude_chains = true;
  c.goal_atoms = {{"pickup", {"(has $1 $2)"}},
                  {"handover", {"(has $2 $3)", "(pickedup-by $1 $3)"}},
                  {"unlock", {"(unlocked-by $1 $3)", "(unlocked-with $2 $3)"}}};
  c.goal_variables = GoalVariables::Existential;
  return c;
}

inline LanguageConfig virtual_home_language() {
  LanguageConfig c;
  c.domain = "virtual-home";
  c.salient_actions = {{"grab", 1, 2}};
  c.qualifier = "itemtype";
  c.qualifier_object_arg = 1;
  c.speaker = "actor";
  c.listener = "helper";
  c.max_command_actions = 4;
  c.max_action_types = 2;
  c.max_qualifier_values_per_action_type = 2;
  c.variable_naming = VariableNaming::QualifierValue;
  c.printed_form = PrintedForm::QualifiedArgsOnly;
  c.paper_speaker_actions = SpeakerActionRule::ExcludeAll;
  c.goal_atoms = {{"grab", {"(placed $2 table1)"}}};
  c.goal_variables = GoalVariables::LowercasedName;
  return c;
}

}  // namespace clips::commands
