#pragma once
// The literal listener: given the state in
// which an instruction is spoken, list every command the robot could be asked
// to do there, score the utterance under each command's few-shot prompt, and
// return the posterior over commands. Also: mapping a command to its goal and
// checking it against a plan, and the factory for the LM backends.
//
// The functions take a grounded task and a state rather than a dataset, so the
// listener works on any problem of the two domains (the CLI does the dataset
// loading).
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "commands/command.hpp"
#include "commands/fewshot.hpp"
#include "commands/language_config.hpp"
#include "commands/term.hpp"
#include "lm/language_model.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "util/choices.hpp"

namespace clips::language {

// ---- language-model backends ----------------------------------------------

struct LanguageModelOptions {
  // openai: "" falls back to $CLIPS_LM_BASE_URL / $CLIPS_LM_MODEL / $OPENAI_API_KEY
  // and then to the backend's own defaults (see lm/openai_model.hpp).
  std::string base_url;
  std::string model;
  std::optional<std::string> api_key;
  // openai: seconds one HTTP attempt may take (0 = the backend's default).
  double timeout_seconds = 0;
  // openai: largest reply accepted, in MiB (0 = the backend's default, 16).
  double max_reply_mb = 0;
  // openai: prompts per request (0 = the backend's default, 16); one prompt
  // per request, sent as a string (Ollama refuses an array); vLLM's
  // prompt_logprobs instead of echo (nullopt: $CLIPS_LM_PROMPT_LOGPROBS);
  // max_tokens=1 from the start (a server known to refuse 0).
  std::size_t batch_size = 0;
  bool single_prompt = false;
  std::optional<bool> prompt_logprobs;
  bool max_tokens_one = false;
  // embedded: directory of the corpus files ("" = the backend's default).
  std::string data_dir;
};

// The backends make_language_model builds, as a name table (util/choices.hpp;
// the first is the default).
enum class LanguageModelKind { Embedded, OpenAi };
util::Choices<LanguageModelKind>& language_model_choices();
// Names accepted by make_language_model, default first.
std::vector<std::string> language_model_kinds();

// What an openai server said to one short scoring request: the one line to
// show the user and the options adapted to what the server takes (a single
// prompt, max_tokens=1, prompt_logprobs). Throws LmError, whose message is
// that line, when the server cannot score a given text or cannot be reached.
struct ServerCheck {
  std::string line;
  LanguageModelOptions options;
};
ServerCheck check_language_model_server(const LanguageModelOptions& options);

// "embedded" (or "") -> EmbeddedLanguageModel, "openai" -> OpenAiCompletionsModel,
// each wrapped in a CachedLanguageModel because inference and the listener
// re-score the same (prompt, utterance) pairs. Throws clips::InputError for an
// unknown kind (listing the known ones); backend construction errors (LmError)
// pass through.
std::shared_ptr<lm::LanguageModel> make_language_model(const std::string& kind,
                                                       const LanguageModelOptions& options = {});

// The model for one domain's utterances. Not embedded: make_language_model.
// Embedded: trained on the pack's hand-written corpora when it lists them
// (the paper packs), else on a corpus generated from the domain's PDDL and
// command language over the given problems (lm/domain_corpus.hpp). The
// prompts' few-shot examples are trained on in both cases.
// `goal_names`: the candidate goals' labels, for statements of the goal
// (lm::DomainDescription::goal_names; empty: no statements of the goal).
std::shared_ptr<lm::LanguageModel> make_domain_language_model(const std::string& kind, const LanguageModelOptions& options,
                                                              const domains::Pack& pack, const pddl::Domain& domain,
                                                              const std::vector<const pddl::Problem*>& problems,
                                                              const std::vector<std::string>& goal_names = {});
// The same over every problem a dataset's plans use.
// The WordNet noun senses the embedded model gives a dataset's type names
// where they are not the first (lm::domain_noun_senses, over every problem),
// for `clips validate`; empty for a pack with a hand-written corpus, which
// does not use them.
lm::NounSenses dataset_noun_senses(const data::Dataset& dataset);
// For the same types (lm::domain_noun_types, over every problem): the
// WordNet noun each is read as (lm::WordNetLexicon::type_noun; empty: none),
// for `clips validate`; empty for a pack with a hand-written corpus.
std::map<std::string, std::string> dataset_type_nouns(const data::Dataset& dataset);

// The model every front end hears a dataset's sessions with (`clips infer`,
// `bench`, `serve`, Python and C++ sessions opened on the folder): the
// embedded model over the problems of its recorded plans and their candidate
// goals (a folder without plans: over every problem), or the pack's corpora.
std::shared_ptr<lm::LanguageModel> make_dataset_language_model(const std::string& kind,
                                                               const LanguageModelOptions& options,
                                                               const data::Dataset& dataset);

// Scores one request under each prompt block the problems use (the speaker
// model's for each problem's numbered places, the literal listener's, the
// empty prompt's), so that the embedded model trains or loads them now, side
// by side, rather than at the first instruction. Errors are ignored: a
// warm-up only (the bench before its plans, `clips serve` before it listens).
void warm_up_language_model(lm::LanguageModel& lm, const data::Dataset& ds, const std::vector<std::string>& problem_ids);

// ---- listener setup ---------------------------------------------------------

struct LiteralListenerSetup {
  domains::PackPtr pack;            // the domain: candidates, qualifiers, variable types
  commands::LanguageConfig config;  // the pack's command language (a copy callers may adjust)
  std::vector<commands::FewShotExample> examples;  // the literal examples, in prompt order
  // Summed log-probabilities are divided by this (the pack's literal_listener
  // temperature): 1 for mDKG, 0.5 for VH (the reference queries davinci-002
  // at temperature 0.5 and scales the scores).
  double temperature = 1.0;
};

// The directory of fewshot-examples.tsv and prompt-orders.json: the language/
// folder of util::data_dir() (the embedded LM reads its corpus from there too).
std::string language_data_dir();

// Setup for a domain pack: its language config, its literal few-shot
// examples in prompt order, and its listener temperature. Throws
// clips::InputError if the pack has no literal listener or its data files
// are unreadable.
LiteralListenerSetup literal_listener_setup(domains::PackPtr pack, const std::string& data_dir = "");
// The same for a built-in pack by name ("doors-keys-gems", "virtual-home").
LiteralListenerSetup literal_listener_setup(const std::string& domain, const std::string& data_dir = "");

// ---- candidates and commands --------------------------------------------------

// The ground salient listener actions of the literal listener in state `s`
// (Pack::literal_candidates):
// mDKG: (pickup robot k) for every key, (handover robot human k) for
// every key, (unlock robot k d) for every key/door pair of the same colour, in
// that order (keys and doors in declaration order), dropping only actions that
// are statically impossible (forbidden items); held or used keys are kept.
// VH: (grab helper i f) for every (placed i f) in `s`, ordered by
// fixture name, then item name. Other packs: every ground salient action of
// the listener.
std::vector<commands::Term> literal_candidate_actions(const pddl::Task& task, const pddl::State& s,
                                                      const domains::Pack& pack);

// The distinct lifted commands over those candidates (at most K actions each, K from
// setup.config: 3 for mDKG, 4 for VH), in enumeration order.
std::vector<commands::Command> literal_commands(const pddl::Task& task, const pddl::State& s,
                                                const LiteralListenerSetup& setup);

// ---- scoring ------------------------------------------------------------------

struct RankedCommand {
  commands::Command command;
  double log_likelihood = 0;  // LM log P(utterance | prompt(command)) divided by the temperature
  double prob = 0;            // posterior under a uniform prior
};

struct ListenerResult {
  std::string utterance;               // as given (without the added space/stop)
  std::vector<RankedCommand> commands; // by decreasing probability (ties keep enumeration order)
};

// Scores `utterance` under every command in ONE lm.score() call. The
// continuation is utterance_continuation(utterance) (leading space, "\n" stop).
// Throws clips::InputError if the utterance is empty or whitespace only.
ListenerResult rank_commands(const std::vector<commands::Command>& commands, const std::string& utterance,
                             const LiteralListenerSetup& setup, lm::LanguageModel& lm);

// literal_commands + rank_commands.
ListenerResult literal_listener(const pddl::Task& task, const pddl::State& s, const std::string& utterance,
                                const LiteralListenerSetup& setup, lm::LanguageModel& lm);

// ---- commands as goals ----------------------------------------------------------

// The goal formula of a command compiled in `task`.
pddl::CompiledCondition compile_command_goal(const pddl::Task& task, const commands::Command& command,
                                  const commands::LanguageConfig& config);

// The state after the observed plan and then its completion (the completed plan
// continues from the end of the observed one). Throws InputError at a
// bad step.
pddl::State completed_final_state(const pddl::Task& task, const pddl::PlanFile& observed,
                                  const pddl::PlanFile& completed);

// Whether `state` satisfies the command's goal formula.
bool state_satisfies_command(const pddl::Task& task, const pddl::State& state,
                             const commands::Command& command, const commands::LanguageConfig& config);

// The facts achieved along a trajectory: every dynamic atom that is true in at
// least one of `states` (numeric fluents as in the last state). Command goals
// are positive conjunctions over atoms (plus static colour/type facts and
// object inequalities), so evaluating one here asks "did each thing the
// command asks for happen at some point?".
pddl::State achieved_facts(const pddl::Task& task, const std::vector<pddl::State>& states);

// Whether the completed plan fulfils the command: its goal holds in the
// achieved facts of s_T and the completion's states (observed + completion,
// from the initial state). Neither the final state nor any single state will
// do: a key handed over is usually spent on a door later, which deletes
// (has human key), so "pass me the red keys" (two hand-overs) may never hold
// at one instant although the plan did exactly that.
bool completed_plan_satisfies(const pddl::Task& task, const pddl::PlanFile& observed, const pddl::PlanFile& completed,
                              const commands::Command& command, const commands::LanguageConfig& config);

}  // namespace clips::language
