#pragma once
// The experiment runner behind `clips bench` and `clips assist`: for one
// dataset plan, run inference once (three modalities), assistance for every
// method, and score each run with the paper's metrics (eval/metrics.hpp).
#include <chrono>
#include <exception>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "assist/assist.hpp"
#include "clips/types.hpp"
#include "engine/runs.hpp"
#include "multimodal/multimodal.hpp"
#include "inference/belief.hpp"
#include "inference/utterance_model.hpp"
#include "lm/language_model.hpp"

namespace clips::eval {

// One method's result row on one plan (the methods: eval/methods.hpp).
struct MethodResult {
  std::string method;
  std::optional<double> p_true_goal;  // inference methods only
  std::vector<double> goal_posterior;
  // Inference methods: the goal posterior after each observed step ([0]: at s_0).
  std::vector<std::vector<double>> posterior_steps;
  double precision = 0, recall = 0;
  double plan_length = 0, human_cost = 0, plan_cost = 0;
  double rel_plan_length = 0, rel_human_cost = 0;  // / CLIPS offline Q_MDP on the same plan
  bool has_relative = false;  // rel_* are set: the "clips" method ran on this plan
  double goal_success = 0;
  std::map<std::string, double> options;
  std::vector<pddl::ActionId> actions;  // executed actions (the most likely run)
  std::vector<std::string> plan;        // the same, printed

  std::vector<double> decision_seconds;  // per assistant decision (Q_MDP)
  std::vector<std::string> ties;         // the request rule's ties (assist::AssistResult::ties)
  // Whether the assistant did what the instruction explicitly asked of it
  // (PlanOutcome::requested, eval/requested.hpp); nullopt: nothing asked.
  std::optional<bool> request_done;
  double seconds = 0;
  // (issue 8) A method that failed on this plan (e.g. the multimodal endpoint
  // or its answer); such results are left out of the aggregates.
  std::string error;
  std::exception_ptr failure;  // what set `error`, so a caller can rethrow it with its type
  std::vector<std::string> notes;  // e.g. multimodal actions that were skipped
};

struct PlanOutcome {
  std::string plan_id;
  std::vector<std::string> goals;
  int true_goal = -1;
  std::vector<std::string> true_options;
  std::vector<MethodResult> methods;
  double seconds = 0;
  std::string error;  // non-empty when the plan could not be evaluated
  std::vector<std::string> utterance_warnings;  // inference::InferenceRun::utterance_warnings
  std::exception_ptr failure;  // the exception behind `error` (its type tells input from LM failures)
  // (issue 8) CLIPS goal posterior after each observed step ([0]: at s_0), for pictures.
  std::vector<std::vector<double>> goal_posterior_steps;
  // From the dataset's instructions.tsv (data::PlanRecord): "dev", "test" or
  // "" and the instruction's categories; and the step whose posterior is the
  // one after the (last) instruction (-1: the plan has none).
  std::string split;
  std::vector<std::string> categories;
  int instruction_step = -1;
  // What the instruction explicitly asked the assistant to bring about
  // (data::PlanRecord::requested); empty: nothing.
  std::string requested;
  // (issue 43) The inference's per-step times ([0]: the start at s_0), wall
  // and summed over its refinement threads (StepRecord::work_seconds: the
  // time on one thread), and those threads.
  std::vector<double> step_seconds, step_work_seconds;
  int inference_threads = 1;
  const MethodResult* find(const std::string& m) const;
};

struct ExperimentOptions {
  std::vector<std::string> methods;  // empty: all default methods of the domain
  bool all_assistance = false;       // add qmdp_online and pibar for the IP methods
  uint64_t seed = 1;
  // The CLIPS speaker model's command rule (paper or the reference code's).
  inference::SpeakerRule speaker_rule = inference::SpeakerRule::Paper;
  // Which plans the speaker model may mean; nullopt: the pack's.
  std::optional<domains::RolloutSettings::Plans> speaker_plans;
  // The utterance model's noise (InferenceOptions::utterance_noise); nullopt: the pack's.
  std::optional<double> utterance_noise;
  // Its exponent (InferenceOptions::utterance_exponent); nullopt: the pack's.
  std::optional<double> utterance_exponent;
  inference::UtteranceTiming utterance_timing = inference::UtteranceTiming::After;
  inference::AssistantTurns assistant_turns = inference::AssistantTurns::Taken;
  // Which Q-values Q_MDP floors at the cost of waiting to the horizon.
  assist::QaFloor qa_floor = assist::QaFloor::DeadEnds;
  // How Q_MDP breaks ties (assist::AssistRule); nullopt: the pack's assistance_rule.
  std::optional<assist::AssistRule> assist_rule;
  // Threads per inference (InferenceOptions::threads): 1 when plans already
  // run in parallel (`clips bench`), 0 (all cores) for a single plan.
  int inference_threads = 1;
  // Particle inference (the one particle options type); particles 0: exact.
  ParticleOptions particles;
  // (issue 8) The multimodal-LLM baseline's chat endpoint; with the default
  // method list it runs only when configured().
  multimodal::MultimodalOptions multimodal;
  // Node budget of each lookahead search of inference and assistance
  // (InferenceOptions::refine.max_nodes); 0: the default, 2^18.
  size_t refine_max_nodes = 0;
  // Wall-clock deadline of the whole run (`clips assist --time-limit`): every
  // search of inference and of the assistance episodes ends there. max(): none.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Called with the inference run before assistance starts (timings, budget
  // stops: `clips bench --scaling`).
  std::function<void(const inference::InferenceRun&)> on_inference;
};

std::vector<std::string> default_methods(const domains::Pack& pack, bool all_assistance);
// Every method name evaluate_plan accepts on this kind of domain.
std::vector<std::string> known_methods(const domains::Pack& pack);
// Whether `name` is a method of some domain (known_methods of any pack), for
// reading results without the pack (`clips bench merge`).
bool is_method_name(const std::string& name);

// Assisting a live human: inference over observations that are not a dataset
// plan (built by the caller; see engine::run_inference_on_observations),
// then one decision of the assistant in the state they lead to by the
// registered policy `assistance`, with the posterior of `method` (clips,
// lang_only or action_only).
// Driven by the session engine (src/engine), as clips::Session and the
// server decide; `limits` bound the whole call (inference and decision).
struct LiveDecision {
  std::vector<std::string> goals;     // candidate goal labels
  std::string next_actor;             // who acts next in the final state
  std::optional<std::string> action;  // the assistant's choice; nullopt on the principal's turn
  std::vector<double> goal_posterior; // the weights behind it, per goal
  AssistDecision decision;            // the whole decision (engine/json.hpp writes it)
  Posterior posterior;                // the method's posterior after the observations
};
LiveDecision decide_next_action(const data::Dataset& ds, const data::PlanRecord& observations,
                                std::shared_ptr<lm::LanguageModel> lm, const ExperimentOptions& opts,
                                const std::string& method, Assistance assistance = Assistance::QMdp,
                                const CallLimits& limits = {});

// Runs every requested method on one plan. Thread-safe for distinct Datasets.
PlanOutcome evaluate_plan(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                          const ExperimentOptions& opts);

// `clips validate`'s rehearsal of `clips bench` on one plan, through the same
// code with tiny budgets (the options' refine_max_nodes, default 256 nodes,
// and a two-step assistance horizon): inference in its three modalities (CLIPS
// with the utterance, language-only, action-only), then every method bench
// would run (opts.methods, else the pack's defaults) from s_T, then what such
// a short run may not reach: the goal of a command for each salient action
// (language.goal_atoms) and the assistance options. What bench would stop at
// (a predicate or object the task lacks, the no-op or turn atom of an agent, a
// goal atom naming a missing argument, an unreadable few-shot file) is a
// failure naming the method or check; a salient action with no goal atoms is
// a warning (is_missing_goal_atoms).
struct BenchCheck {
  std::string plan_id;
  std::vector<std::string> passed;                            // methods whose set-up ran
  std::vector<std::pair<std::string, std::string>> failures;  // (method or check, error)
  std::vector<std::string> warnings;
};
BenchCheck check_bench_setup(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                             const ExperimentOptions& opts);
// Whether an error says that a command's action has no language.goal_atoms.
// check_bench_setup reports it as a warning: goal atoms are to be derived
// from the actions' effects (then the literal listener no longer stops at it).
bool is_missing_goal_atoms(const std::string& error);

}  // namespace clips::eval
