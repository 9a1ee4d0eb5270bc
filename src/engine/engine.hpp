#pragma once
// The session engine: the one live loop under every front end (clips::Session,
// the server's sessions, `clips assist --problem`, the bench's live decisions).
// It owns the belief over hypotheses (goal x cost profile), their policies,
// the decision rule (Q_MDP, pi-bar or the literal listener, through
// src/assist), the trace of steps, and the JSON form of all of them
// (engine/json.hpp). docs/architecture.md draws the layering.
//
// Every call that searches (observe, hear, assist, undo) takes CallLimits: a
// wall-clock limit and a cancellation token. When either fires the call
// throws TimeLimitError or CancelledError and the engine is unchanged: the
// update runs on a copy of the belief, swapped in only on success.
//
// Not thread-safe: one call at a time per engine (distinct engines share
// nothing mutable).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clips/errors.hpp"
#include "clips/types.hpp"
#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "lm/language_model.hpp"
#include "pddl/task.hpp"

namespace clips::inference {
class Belief;
struct InferenceOptions;
struct StepRecord;
}

namespace clips::engine {

// What an engine plays: a grounded problem, its pack, the candidate goals and
// cost profiles, and the reference plan when there is one.
struct Problem {
  std::string dataset;  // the dataset's name; "" for PDDL text or a domain folder
  std::string problem;  // the problem's id in the dataset, or its PDDL name
  std::shared_ptr<const data::Dataset> owner;  // keeps `plan` alive (null without a dataset)
  const data::PlanRecord* plan = nullptr;      // the reference plan; null: none
  std::shared_ptr<const pddl::Task> task;
  domains::PackPtr pack;
  std::vector<data::GoalSpec> goals;
  std::vector<model::CostProfile> profiles;
  int true_goal = -1;  // index in goals; -1: unknown
};

// A problem of a dataset with `plan` (may be null) as its reference: the
// plan's candidate goals, cost profiles (its tag) and true goal; without a
// plan, the pack's goal rule for the problem and its default profiles.
Problem dataset_problem(std::shared_ptr<const data::Dataset> ds, std::string name, const std::string& problem_id,
                        const data::PlanRecord* plan);
// A dataset directory and a problem id ("2") or plan id ("2.1.keys"); the
// session starts at the problem's initial state either way.
Problem dataset_problem(const std::string& dataset_dir, const std::string& problem_or_plan);
// Where a problem's candidate goals come from when the caller has its own:
// `conditions` (PDDL conditions) replace the pack's goal rule; else `hint`
// is added to the goal rule's errors (what the caller may give instead).
struct GoalChoice {
  std::vector<std::string> conditions;
  std::string hint;
};
// A domain folder (domain.pddl, maybe pack.json) and a problem file.
Problem domain_problem(const std::string& domain_dir, const std::string& problem_file, const GoalChoice& goals = {});
// A domain and problem as PDDL text with the pack as JSON text ("": the pack
// the domain's name finds). `labels` name the three texts in errors.
struct TextLabels {
  std::string domain = "<domain text>", problem = "<problem text>", pack = "<pack text>";
};
Problem text_problem(const std::string& domain_pddl, const std::string& problem_pddl, const std::string& pack_json,
                     const TextLabels& labels = {}, int64_t max_ground_actions = 0, const GoalChoice& goals = {});

// A problem drawn at random by the pack of a domain folder (as `clips
// generate` draws them: Pack::generate_problem, e.g. counts {"gem": 3,
// "key": 2, "door": 1} for Doors-Keys-Gems), from `seed`. InputError when the
// pack cannot generate, or no draw of `attempts` gave a layout.
Problem generated_problem(const std::string& domain_dir, const domains::GenerateParams& params, uint64_t seed,
                          int attempts = 100);

// How the latest instruction was read (for explanations): for the inference
// methods, commands weighted by the goal posterior; for the literal listener,
// its ranking.
struct Reading {
  std::string utterance;
  std::string source;
  bool scored = false;  // the belief scored it (evidence_weight and warning are set)
  double evidence_weight = 1;
  std::string warning;
  // One reading: a command's display form and its probability; `goal`, for
  // a goal statement ("(make me ?goal1) where (named ?goal1 ...)", alone or
  // joined to a command), the label of the candidate goal it states (the most
  // probable one, should two goals' statements read alike), else empty.
  struct Command {
    std::string command;
    double p = 0;
    std::string goal;
  };
  std::vector<Command> commands;  // most probable first
};

// One point per belief update (start, each action, each utterance).
struct HistoryPoint {
  std::string label;  // "start", the action, or the quoted utterance
  std::vector<double> goals;
};

class Engine {
 public:
  // `lm`: the language model utterances are scored with; null: built at the
  // first utterance from options.language_model (shared by engines on the
  // same domain and problem).
  Engine(Problem problem, SessionOptions options, std::shared_ptr<lm::LanguageModel> lm = nullptr);
  // The batch form: the belief with `inference` as given (the bench's and
  // `clips infer`'s settings), started with `heard_at_start` scored in the
  // start's step.
  Engine(Problem problem, SessionOptions options, const inference::InferenceOptions& inference,
         std::shared_ptr<lm::LanguageModel> lm, const std::vector<std::string>& heard_at_start = {},
         const CallLimits& limits = {});
  // Recorded observations (a plan file's actions and its annotated
  // utterances) replayed through observe and hear, under the utterance
  // timing of `inference`: the one loop behind `clips infer`, the bench and
  // Python's run_plan. InputError at the first action that is not the
  // problem's or not applicable.
  static Engine replay(Problem problem, SessionOptions options, const inference::InferenceOptions& inference,
                       std::shared_ptr<lm::LanguageModel> lm, const pddl::PlanFile& observed);
  Engine(Engine&&) noexcept;
  Engine& operator=(Engine&&) noexcept;
  ~Engine();

  // ---- calls that change the engine (all or nothing) ----
  // An action of either agent. InputError: not an action of the problem;
  // InapplicableActionError: its precondition is false now.
  const Step& observe(const std::string& action, const CallLimits& limits = {});
  const Step& observe(pddl::ActionId action, const CallLimits& limits = {});
  // An action with the utterances heard just before it, in the state it is
  // taken in: they are scored in the action's step (the datasets' timing).
  const Step& observe(pddl::ActionId action, const std::vector<std::string>& heard_before,
                      const CallLimits& limits = {});
  // An utterance heard in the current state. InputError for empty or
  // non-UTF-8 text; LanguageModelError when the model fails.
  const Step& hear(const std::string& utterance, const CallLimits& limits = {});
  // Several utterances heard together, in one update.
  const Step& hear(const std::vector<std::string>& utterances, const CallLimits& limits = {});
  // Takes back the principal's latest move or instruction with everything
  // after it (the assistant's actions); false (and nothing changes) when
  // there is none.
  bool undo(const CallLimits& limits = {});
  // Back to the start.
  void reset();
  void set_method(Method m);

  // The assistant's next action under the method (default: the engine's)
  // and assistance rule; nothing changes (the policies are refined on
  // copies). On the principal's turn: assistant_turn false, no action.
  AssistDecision assist(const CallLimits& limits = {}) { return assist(method(), limits); }
  AssistDecision assist(Method method, const CallLimits& limits = {});

  // ---- reading ----
  Method method() const;
  const SessionOptions& options() const;
  const Problem& problem() const;
  const pddl::Task& task() const;
  const std::shared_ptr<const pddl::Task>& task_ptr() const;
  const domains::Pack& pack() const;
  const pddl::State& state() const;                 // s_t
  const pddl::State* previous_state() const;        // before the last action; null at the start
  int t() const;                                    // actions observed so far
  Posterior posterior() const { return posterior(method()); }
  Posterior posterior(Method m) const;
  const std::vector<Step>& trace() const;           // trace()[t]: after t actions, in the engine's method
  std::vector<HistoryPoint> history(Method m) const;
  std::vector<HistoryPoint> history() const { return history(method()); }
  // The actions and utterances so far, in order (the undo/replay log).
  struct Event {
    bool utterance = false;
    std::string text;  // the action's name or the utterance
    // Where an utterance was scored: heard on its own (hear), in the start's
    // step, or in the step of the action after it.
    enum class Scored { Heard, AtStart, WithNextAction } scored = Scored::Heard;
  };
  const std::vector<Event>& events() const;
  std::string active_agent() const;                 // the pack's principal or assistant
  bool assistant_turn() const;
  bool principal_action(pddl::ActionId a) const;    // acted by the principal
  std::vector<CandidateAction> applicable_actions() const;
  // Whether candidate goal `goal` (index) holds now; the first that does.
  bool goal_holds(int goal) const;
  // The same for a goal's label; InputError naming the candidates for another.
  bool goal_holds(const std::string& label) const;
  std::optional<int> reached_goal() const;
  const std::vector<std::string>& goal_labels() const;
  const std::vector<std::string>& profile_names() const;
  std::optional<Reading> reading(size_t top = 5) const;  // null before any instruction
  // The belief's own records (records()[t]: after t actions, every modality)
  // and the belief: what a batch run reports (engine/runs.hpp).
  const std::vector<inference::StepRecord>& records() const;
  std::shared_ptr<const inference::Belief> belief() const;
  // Inference statistics.
  size_t searches_stopped_by_budget() const;
  size_t refinements() const;
  int refine_threads() const;

 private:
  struct Impl;
  explicit Engine(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace clips::engine
