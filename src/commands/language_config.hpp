#pragma once
// Per-domain settings of the command model. Everything domain-specific about commands lives here so the
// enumeration, lifting and printing code works on plain strings for any domain.
//
// Defaults follow the reference code: all speaker actions are
// removed before enumeration and chained actions are allowed.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace clips::commands {

// An action name that is salient, with 1-based argument positions.
struct SalientActionRule {
  std::string action;  // e.g. "handover"
  int agent_arg = 1;   // the acting agent
  int focal_arg = 2;   // the object the action is about (handover: the item, unlock: the door)
  // The argument naming where the action leaves its focal object ((put A I P)
  // adds (in I P): 3), found from the domain when the pack is built
  // (domains::derive_destinations); 0: none.
  int destination_arg = 0;
  // Whether the focal object is a place (its parameter's type is a location
  // predicate's place type, as the greenhouse of (unlock A K P Q)), found with
  // destination_arg. A place is named, not lifted, in commands, as it is in
  // location predicates: "unlock the greenhouse" names which one.
  bool focal_is_place = false;
};

// The predicate a command states a destination with: (to ?compost1 rosebed)
// for "take the compost to the rose bed". Not a domain predicate: the speaker
// model adds it to commands, and the language model reads it like a place.
inline constexpr const char* kDestinationPredicate = "to";

// Which speaker actions may appear in commands.
enum class SpeakerActionRule {
  ExcludeAll,               // reference code: drop every speaker action first
  ExcludeSpeakerOnlyCommands  // paper (mDKG): drop commands whose actions are all the speaker's
};

// How lifted variables are named.
enum class VariableNaming {
  ObjectType,     // mDKG: `?key1`, `?door1`: object type + per-type counter
  QualifierValue  // VH: `?Plate1` after (itemtype plate1 plate), else `?Fixture1` after the type
};

// How the command is printed for the LLM.
enum class PrintedForm {
  WhereClause,        // mDKG: actions ` where ` predicates, '?' removed
  QualifiedArgsOnly   // VH: drop unqualified variables and qualifier predicates, lowercase first letter
};

// How variables are treated when a command becomes a goal formula.
enum class GoalVariables {
  Existential,        // mDKG: (exists (?key1 - key) (and ...))
  LowercasedName      // VH quirk: ?Plate2 becomes the constant plate2
};

// The largest max_command_actions a pack may ask for (the paper's packs use 3 and 4).
inline constexpr int kMaxCommandActions = 4;

struct LanguageConfig {
  std::string domain;
  std::vector<SalientActionRule> salient_actions;

  // The qualifying predicate attached to each focal object, e.g. (iscolor key2 red).
  std::string qualifier = "iscolor";
  int qualifier_object_arg = 1;  // 1-based position of the object in the qualifier
  // Further qualifying predicates, same object position, attached after the
  // first (e.g. issize then ismaterial: "the big wooden plank").
  std::vector<std::string> more_qualifiers;

  std::string speaker = "human";
  std::string listener = "robot";
  std::string speaker_pronoun = "me";
  std::string listener_pronoun = "you";

  int max_command_actions = 3;  // K, at most kMaxCommandActions
  // Commands with more than this many actions may use at most this many
  // distinct (agent, action name) pairs (the reference checks n > 2 only).
  int max_action_types = 2;
  // Within one (agent, action name) group of such a command, at most this many
  // distinct qualifiers (compared with the object masked). mDKG: 1 (colour
  // consistency); VH: 2 (at most 2 item types); 0 disables the check.
  int max_qualifier_values_per_action_type = 1;

  SpeakerActionRule speaker_actions = SpeakerActionRule::ExcludeAll;
  // Paper rule: drop commands in which an object occurs in two actions.
  bool exclude_chains = false;
  // The same two settings as the paper describes them for the CLIPS speaker
  // model. The speaker model uses these by default
  // (inference::SpeakerRule::Paper); the literal listener always uses the two
  // fields above. mDKG: speaker-only commands dropped, chains dropped; VH:
  // every speaker action dropped (the paper's VH rule equals the code's).
  // Default: the speaker's own part stays in joint commands, so "I'll get
  // the cheese, can you get the pan?" is read as the plan it states.
  SpeakerActionRule paper_speaker_actions = SpeakerActionRule::ExcludeSpeakerOnlyCommands;
  bool paper_exclude_chains = false;

  VariableNaming variable_naming = VariableNaming::ObjectType;
  PrintedForm printed_form = PrintedForm::WhereClause;
  // Print only the pronouns and the focal object of each action for the
  // language model ("(pickup you plank1)", not "(pickup you plank1 rack)"):
  // places and instruments people leave unsaid stay in the goal.
  bool print_agents_and_focal_only = false;

  // Predicates that say where an object is, e.g. (on plank1 rack): facts of
  // the scoring state that the speaker model attaches to a command's objects
  // as it does qualifiers, keeping the place by name, so that "the plank from
  // the rack" can be read. The object is their first argument, the place
  // the second. `locations_auto`: found from the domain when the pack is
  // built (domains::derive_location_predicates); the pack's "locations":
  // "auto" (default), "none", or a list of predicate names.
  std::vector<std::string> location_predicates;
  bool locations_auto = true;
  // Whether the speaker model's commands state where an action leaves its
  // object (SalientActionRule::destination_arg), so "put the compost at the
  // border" tells the jobs at the border from the others. The pack's
  // "destinations": true (default) or false (the paper packs).
  bool destinations = true;
  // The share of the speaker's utterances that state the goal itself ("we're
  // making the frame", "I want the red gem") rather than a command: the
  // speaker model scores them under the goal's statement, (make me ?goal1)
  // where (named ?goal1 frame) ... (inference::UtteranceModel). 0: commands
  // only (the paper's model; its packs keep it for their tables).
  double goal_statements = 0.15;
  // Of those, the share that also say what they want done ("Distillation
  // next; could you dig the instrument out?"): scored under the goal's
  // statement joined to each command of the plans.
  double goal_with_command = 0.5;
  bool is_location(const std::string& predicate) const;
  // A location predicate or the destination one: its second argument is a
  // place, printed by name.
  bool names_place(const std::string& predicate) const;

  // Goal atoms per action name; `$i` is replaced by the action's i-th argument
  // after pronouns are mapped back to agent names. E.g. handover ->
  // {"(has $2 $3)", "(pickedup-by $1 $3)"}.
  std::map<std::string, std::vector<std::string>> goal_atoms;
  GoalVariables goal_variables = GoalVariables::Existential;
  // Objects of the task that people tell apart by the number in their name
  // ("shelf 3" for shelf3 beside shelf1 and shelf2): a command that names one
  // prints it with its number marked (util::number_marked), so the language model
  // reads the number as a word of its own. Set per task (numbered_names);
  // empty in a pack.
  std::vector<std::string> numbered_names;

  const SalientActionRule* salient_rule(const std::string& action) const;
  // `qualifier` then `more_qualifiers`.
  std::vector<std::string> qualifiers() const;
  bool is_qualifier(const std::string& predicate) const;
  // Maps an agent name to its pronoun and back; other names pass through.
  std::string to_pronoun(const std::string& name) const;
  std::string to_agent_name(const std::string& arg) const;
  bool is_pronoun(const std::string& arg) const {
    return arg == speaker_pronoun || arg == listener_pronoun;
  }
};

// Loads a language.json file (format: data/domains/<domain>/language.json;
// enum values are kebab-case, e.g. "exclude-speaker-only-commands"). Missing keys keep the defaults above; unknown
// keys and bad values raise clips::InputError naming the file and the key.
LanguageConfig load_language_config(const std::filesystem::path& path);
LanguageConfig parse_language_config(const std::string& json_text, const std::string& source_name);

}  // namespace clips::commands
