#pragma once
// A training corpus for the embedded utterance model, generated from a
// domain's command grammar, for a domain that ships no hand-written corpus.
//
// The input is the domain as plain strings (no PDDL types from pddl/ or
// domains/: this layer must not depend on them): action schemas with their
// parameter types, the type hierarchy, a problem's objects and qualifier facts
// such as (issize plank1 big), and the command grammar (which actions a
// command may hold, where their agent and focal object are, the pronouns).
// From it come (command, utterance) pairs:
//   (handover you me plank1) where (issize plank1 big)  <->  "Could you hand me the big plank?"
// Commands are printed like the few-shot examples: pronouns for the two
// agents, the focal object as a variable named by its type and a per-type
// counter, the recipient pronoun of hand-over-like actions, other arguments
// (stations, tools of the act) left out, then `where` and the focal objects'
// qualifier facts. Utterances put request frames ("can you ...", "please
// ...", "I need ...") around verb and noun phrases made from the PDDL names
// (WordNetLexicon::verb_phrases / noun_phrases), qualifier values as
// adjectives ("the big plank", "the metal one"), and cover two-action and
// joint commands ("I'll get the saw, can you bring me the big plank?").
// Generation is deterministic: a fixed-seed generator and ordered inputs.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lm/embedded_model.hpp"
#include "lm/training_pair.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

class AlignmentModel;

struct DomainActionSchema {
  std::string name;                          // "handover"
  std::vector<std::string> parameter_types;  // {"agent", "agent", "item", "station"}
};

struct DomainObject {
  std::string name;  // "plank1"
  std::string type;  // "plank"
};

// A two-argument qualifier fact of the problem, (predicate object value).
struct QualifierFact {
  std::string predicate;  // "issize"
  std::string object;     // "plank1"
  std::string value;      // "big"
};

// An action a command may hold, with 1-based parameter positions (as in a
// domain's language.json "salient_actions").
struct CommandActionRule {
  std::string action;  // "handover"
  int agent_arg = 1;   // the acting agent
  int focal_arg = 2;   // the object the action is about
  int destination_arg = 0;  // where the action leaves it ((put A I P): 3); 0: none
  bool focal_is_place = false;  // the focal object is a place, named in commands ("(unlock you greenhouse)")
};

// Everything the generator needs to know about a domain and one problem.
struct DomainDescription {
  std::vector<DomainActionSchema> actions;
  std::map<std::string, std::string> parent_type;  // "plank" -> "part", "part" -> "item", ...
  std::vector<DomainObject> objects;
  std::vector<QualifierFact> qualifiers;
  // Where objects are at the start, (on plank1 rack): the object, then the
  // place (CommandActionRule's language.location_predicates). Commands may
  // state them ("(pickup you plank1) where (on plank1 rack)" <-> "get the
  // plank from the rack").
  std::vector<QualifierFact> locations;
  // Names of the candidate goals (labels such as "pot-roses" or goal objects
  // such as "frame"), for statements of the goal ("we're making the frame"),
  // which the speaker model reads under (make me ?goal1) where (named
  // ?goal1 frame). Empty: no goal statements in the corpus.
  std::vector<std::string> goal_names;
  std::vector<CommandActionRule> command_actions;
  // The predicate commands state a destination with, (to plank1 bench)
  // (commands::kDestinationPredicate).
  std::string destination_predicate = "to";
  std::string speaker = "human";  // object names of the two agents
  std::string listener = "robot";
  std::string speaker_pronoun = "me";
  std::string listener_pronoun = "you";
  // Optional words a domain pack may add for its own actions and types, tried
  // before the WordNet-derived ones (e.g. "unlock" -> {"open"}).
  std::map<std::string, std::vector<std::string>> extra_verbs;
  // Places people tell apart by their number (commands::numbered_names):
  // commands print them marked ("shelf#3") and utterances say the number
  // ("shelf 3", "the third shelf").
  std::vector<std::string> numbered;
  std::map<std::string, std::vector<std::string>> extra_nouns;
};

struct DomainCorpusOptions {
  uint64_t seed = 0x5eed2024;
  int utterances_per_command = 3;  // for each one-action command
  int two_action_commands = 120;   // sampled commands with two listener actions
  int joint_commands = 120;        // sampled commands with a speaker and a listener action
  int goal_statements = 60;        // statements of the goal
};

// The types commands name as nouns: those of the objects a command may be
// about (the salient actions' focal parameters) and their declared
// ancestors up to those parameter types ("a tool"); places are said by name.
std::vector<std::string> domain_noun_types(const DomainDescription& domain);
// The WordNet noun sense each of those types means, where it is not the
// first (WordNetLexicon::domain_noun_senses over the declared types).
NounSenses domain_noun_senses(const DomainDescription& domain);

// The generated pairs (weight 1, origin "generated <domain-less index>").
// Throws LmError if the grammar names an action the schemas lack or a
// position outside its parameters.
std::vector<TrainingPair> generate_domain_corpus(const DomainDescription& domain,
                                                 const DomainCorpusOptions& options = {});

// Options for an EmbeddedLanguageModel of a domain without a hand-written
// corpus: no corpus files, the generated corpus instead. The few-shot
// examples of each prompt are added by the model itself, as for any domain.
EmbeddedModelOptions embedded_options_for_domain(const DomainDescription& domain,
                                                 const DomainCorpusOptions& options = {});

// A model trained on the generated corpus plus the domain's few-shot
// examples (weighted fewshot_weight each; there may be none).
std::shared_ptr<AlignmentModel> train_domain_model(const DomainDescription& domain,
                                                   const std::vector<TrainingPair>& fewshot,
                                                   double fewshot_weight = 4.0, int em_iterations = 25,
                                                   const DomainCorpusOptions& options = {});

}  // namespace clips::lm
