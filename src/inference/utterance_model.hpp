#pragma once
// The pragmatic speaker: how likely is utterance u
// if the human holds hypothesis h = (g, c) and is in state s?
//
//   1. The joint plans the speaker may have in mind: the policy π_h rolled
//      out from s. Tied (the default): every plan π_h values as well as its
//      greedy one, ties broken every way, plan p weighted w_p as a uniform
//      random tie-break would pick it (search/tied_rollouts.hpp). Single
//      (the paper packs): the one greedy rollout (mDKG: greedy in
//      π_h for <= 100 steps; VH: weighted A* (w = 2) with the principal
//      barred from grabbing), w = 1.
//   2. Keep each plan's salient actions (pickups, hand-overs, unlocks /
//      grabs), each with the qualifier of its focal object, e.g.
//      (iscolor key2 red).
//   3. Enumerate each plan's distinct lifted commands C_p over the listener's
//      salient actions (speaker actions removed), uniform prior 1/|C_p|.
//   4. P(u | s, π_h) = Σ_p w_p Σ_{c in C_p} (1/|C_p|) P_LM(u | prompt(c)); a
//      plan with no command scores the single prompt "\n" with its w_p.
//   5. With the pack's goal_statements share γ > 0 the speaker may instead
//      state the goal: P(u | s, h) = (1 - γ) (step 4) + γ P_LM(u | prompt(G_h))
//      with G_h = (make me ?goal1) where (named ?goal1 w) ... over the words
//      of the goal's label, of the objects its condition names and of their
//      qualifier values ("pot-roses" -> pot, roses; (has human gem1) -> gem,
//      red). So "we're making the frame" is evidence for the frame. A share
//      (language.goal_with_command) of those speakers also give a command
//      in the same breath: each command c of step 3, with its prior, joined
//      to G_h ("Distillation next. Could you dig the instrument out?").
// The per-command posterior P(c | u, s, π_h) is a by-product, with the ground
// actions each command was lifted from (what the assistant would carry out).
// All prompts of all hypotheses (and utterances) go to the LM in one batch.
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "data/dataset.hpp"
#include "commands/command.hpp"
#include "commands/fewshot.hpp"
#include "commands/language_config.hpp"
#include "lm/language_model.hpp"
#include "search/rtaa.hpp"
#include "search/tied_rollouts.hpp"
#include "util/choices.hpp"

namespace clips::inference {

// How the speaker's rollout runs (the pack's inference.rollout):
//   Greedy         mDKG: best_action of the policy, no search
//   WeightedAStar  VH: weighted A* towards g, with the pack's speaker flag
//                  ((nograb speaker)) set first
using RolloutKind = domains::RolloutSettings::Kind;

// Which of the speaker's own actions the CLIPS speaker's commands may hold.
// Paper: joint commands keep the speaker's part ("I'm going
// for the red key, can you get the yellow one?"), commands that are all the
// speaker's and chains on one object are dropped. Code: the reference code's
// default, every speaker action removed before enumeration. We default to the
// paper: with the embedded model it matches the paper's CLIPS row more closely
// (docs/decisions.md); the literal listener is unaffected.
enum class SpeakerRule { Paper, Code };
util::Choices<SpeakerRule>& speaker_rule_choices();
SpeakerRule parse_speaker_rule(const std::string& text);  // "paper" or "code"; throws InputError
std::string to_string(SpeakerRule r);

// Which state explains an utterance annotated after k actions: s_{k-1}
// (Before, the reference code) or s_k (After). See InferenceOptions.
enum class UtteranceTiming { Before, After };
util::Choices<UtteranceTiming>& utterance_timing_choices();
UtteranceTiming parse_utterance_timing(const std::string& text);  // "before" or "after"; throws InputError
std::string to_string(UtteranceTiming t);

struct UtteranceModelOptions {
  SpeakerRule speaker_rule = SpeakerRule::Paper;
  // Which plans the speaker may mean; nullopt: the pack's (inference.rollout.plans).
  std::optional<domains::RolloutSettings::Plans> plans;
  search::TiedRolloutOptions tied;  // Tied: budgets of the tie-breaking rollouts
  int rollout_steps = 100;                 // greedy rollout bound
  size_t astar_max_nodes = size_t{1} << 16;  // weighted-A* rollout budget
  double astar_weight = 2.0;               // weighted-A* rollout: f = g + 2h
  // Directory with fewshot-examples.tsv and prompt-orders.json; empty: the
  // language/ folder of util::data_dir().
  std::string language_dir;
};

struct CommandScore {
  std::string command;    // display form, e.g. "(handover you me ?key1) where (iscolor ?key1 red)"
  double log_lm = 0;      // log P_LM(u | prompt(c))
  double posterior = 0;   // P(c | u, s, π_h)
  double prior = 0;       // P(c | s, π_h): Σ_p w_p / |C_p| over the plans that hold it
  // The ground actions it was lifted from (agent names, as the task prints
  // them), in command order: the listener's part, and the speaker's own.
  std::vector<std::string> listener_actions, speaker_actions;
};

// One joint plan the speaker may have in mind, from the scoring state.
struct SpeakerPlan {
  double weight = 1;  // sums to 1 over a hypothesis' plans
  std::vector<pddl::ActionId> actions;
};
using SpeakerPlans = std::vector<SpeakerPlan>;

struct HypothesisUtterance {
  double log_likelihood = 0;          // log P(u | s, π_h)
  std::vector<CommandScore> commands; // empty: scored with the "\n" prompt
  // What the words ask the assistant to do, for assistance (the request
  // reading, domains::InferenceSettings::request_plans): `commands` and the
  // commands of a sparing plan (the principal's own actions ten times
  // dearer), with their posterior under both. Empty: read the requests off
  // `commands`.
  std::vector<CommandScore> requests;
};

// The request reading of one hypothesis (HypothesisUtterance::requests):
// its speaker model's reading `own` and the same words read under the
// commands of a sparing plan (`alone`), mixed with prior weights 1 - share and share; the commands'
// posteriors under the mixture, the same command from both summed.
std::vector<CommandScore> merge_requests(const HypothesisUtterance& own, const HypothesisUtterance& alone,
                                         double share);

class UtteranceModel {
 public:
  UtteranceModel(std::shared_ptr<const pddl::Task> task, domains::PackPtr pack,
                 const UtteranceModelOptions& options = {});

  const commands::LanguageConfig& config() const { return config_; }
  RolloutKind rollout_kind() const { return rollout_kind_; }
  // Which plans the speaker may mean (options, else the pack's).
  domains::RolloutSettings::Plans plans_rule() const { return plans_; }
  // The speaker's greedy rollout of π_h from s (both agents' actions).
  std::vector<pddl::ActionId> rollout(const search::Policy& policy, const pddl::State& s) const;
  // The distinct lifted commands of that rollout, in enumeration order.
  std::vector<commands::Command> commands_at(const search::Policy& policy, const pddl::State& s) const;
  // The plans the speaker may have in mind at s (step 1 above). Tied refines
  // `policy` at the states where it looks for ties, with the budgets `refine`.
  SpeakerPlans speaker_plans(search::Policy& policy, const pddl::State& s, const search::SearchOptions& refine) const;
  // The one greedy rollout as a plan set (Single), without refining.
  SpeakerPlans single_plan(const search::Policy& policy, const pddl::State& s) const;

  // result[u][h]: the likelihood of utterance u under the plans of
  // hypothesis h at state s. Exactly one LanguageModel::score call (none if
  // there is nothing to score).
  std::vector<std::vector<HypothesisUtterance>> score(const std::vector<SpeakerPlans>& plans, const pddl::State& s,
                                                      const std::vector<std::string>& utterances,
                                                      lm::LanguageModel& lm) const;
  // The same, where the speaker of hypothesis h may also state its goal
  // (step 5): `goals[h]` is its goal statement (goal_statement()).
  std::vector<std::vector<HypothesisUtterance>> score(const std::vector<SpeakerPlans>& plans,
                                                      const std::vector<commands::Command>& goals,
                                                      const pddl::State& s,
                                                      const std::vector<std::string>& utterances,
                                                      lm::LanguageModel& lm) const;
  // The goal statement G_h of a goal (label and condition) in state s.
  commands::Command goal_statement(const std::string& label, const std::string& condition,
                                   const pddl::State& s) const;
  // The same with each policy's single greedy rollout.
  std::vector<std::vector<HypothesisUtterance>> score(const std::vector<const search::Policy*>& policies,
                                                      const pddl::State& s,
                                                      const std::vector<std::string>& utterances,
                                                      lm::LanguageModel& lm) const;

  // The qualifying predicates of an object in state s, one per qualifier
  // predicate that holds (static facts fold into the task).
  std::vector<commands::Term> qualifiers(const std::string& object, const pddl::State& s) const;

 private:
  commands::Term term(pddl::ActionId a) const;
  struct WeightedCommand {
    commands::Command command;
    double weight = 0;
  };
  // Step 3 over a plan set: distinct commands with their prior weights, and
  // the weight of plans with no command (scored with the empty prompt).
  std::vector<WeightedCommand> weighted_commands(const SpeakerPlans& plans, const pddl::State& s,
                                                 double& no_command) const;
  std::vector<commands::Command> plan_commands(const std::vector<pddl::ActionId>& plan, const pddl::State& s) const;

  std::shared_ptr<const pddl::Task> task_;
  commands::LanguageConfig config_;
  RolloutKind rollout_kind_;
  domains::RolloutSettings::Plans plans_;
  UtteranceModelOptions options_;
  std::vector<commands::FewShotExample> examples_;  // pragmatic order
  std::unordered_map<std::string, std::string> type_of_;
  // Per qualifier predicate (config order), per object: candidate values and the atom that says so.
  struct QualifierAtoms {
    std::string predicate;
    std::unordered_map<std::string, std::vector<std::pair<std::string, pddl::Task::AtomRef>>> of_object;
  };
  std::vector<QualifierAtoms> qualifiers_;
  std::optional<pddl::Task::AtomRef> speaker_flag_;  // set on the speaker before a weighted-A* rollout
};

}  // namespace clips::inference
