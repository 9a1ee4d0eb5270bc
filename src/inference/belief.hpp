#pragma once
// Exact Bayesian goal inference.
//
// Model. The human holds a goal specification h = (g, c): a goal g and a cost
// profile c, drawn uniformly from the candidates (mDKG: 4 gems × 2 profiles =
// 8; VH: the problem's goals × unit costs). They plan a joint policy π_h for
// both agents (turns alternate) and, at each step,
//   * act:   a_t ~ Boltzmann(Q_h(s_{t-1}, ·) / T), T unknown with a discrete
//            inverse-gamma prior (temperature.hpp), marginalised exactly;
//   * speak: with p_speak = 0.05, an utterance u ~ P(u | s, π_h)
//            (utterance_model.hpp), where s is the state the speaker was in
//            (s_k for an utterance after k actions; the reference code's
//            s_{k-1} alignment is an option; index 0 at s_0).
// The assistant's own actions are interventions, do(a): they move the state
// but carry no evidence (likelihood 1, temperatures untouched).
//
// Inference. The hypothesis space is small, so every hypothesis is kept with
// its log weight; no sampling. Each hypothesis owns its policy π_h, refined by
// RTAA* at the current state every step (mDKG; 2^18 expansions per A*), or
// fixed at V = -h_g with no search (VH, n_iters = 0), and its temperature
// weights. The log weight is split into an ACTION part (Σ log P(a_t | ...)
// over human actions) and an UTTERANCE part (Σ log P(u | ...), plus the
// constant speak/no-speak factors), so one run yields all three modalities:
//   both        ∝ prior × action part × utterance part   (CLIPS)
//   action-only ∝ prior × action part                    (SIPS-style IP)
//   utterance   ∝ prior × utterance part                 (language-only IP)
// In the language-only model the policies and scoring states still follow the
// observed actions; only the action likelihoods are left out.
//
// Particles (InferenceOptions::particles = N > 0): for hypothesis spaces too
// large to refine every policy each step, each modality keeps N particles
// over hypotheses (particle_belief.hpp: systematic resampling when the ESS
// falls below a threshold, MH rejuvenation over goals). Only hypotheses some
// particle holds (or a rejuvenation move proposes) are brought up to date.
// The belief records the observed history as a list of events (refine at s,
// score a human action at s, score utterances at s); a hypothesis remembers
// how many events it has processed and replays the rest, in order, when its
// likelihood is next needed. Its numbers are then exactly those the exact
// belief would have: the same refinements in the same states, the same
// temperature updates, the same utterance scores (so a hypothesis joining
// late through rejuvenation gets its correct full-history likelihood, and
// each refinement is done at most once per hypothesis). Hypotheses no
// particle holds keep stale policies; see sync_policies for assistance.
#include <array>
#include <chrono>
#include <functional>
#include <limits>
#include <stdexcept>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "inference/particle_belief.hpp"
#include "inference/temperature.hpp"
#include "inference/utterance_model.hpp"
#include "lm/language_model.hpp"
#include "model/spec.hpp"
#include "search/rtaa.hpp"
#include "util/worker_pool.hpp"

namespace clips::inference {

enum class Modality { Both = 0, UtteranceOnly = 1, ActionOnly = 2 };
inline constexpr std::array<Modality, 3> kModalities = {Modality::Both, Modality::UtteranceOnly, Modality::ActionOnly};
util::Choices<Modality>& modality_choices();
std::string to_string(Modality m);  // "both", "utterance", "action"
Modality parse_modality(const std::string& text);  // throws InputError

// Candidate cost profiles of a plan and the index of the true one, from its
// pack (mDKG: keys plans {C3, C4} (true C3), doors plans {C1, C2} (true C1);
// VH: unit costs). Throws InputError naming the plan for a tag the pack rejects.
using domains::ProfileSet;
ProfileSet plan_cost_profiles(const domains::Pack& pack, const data::PlanRecord& plan);

// What a belief step refines at the assistant's turns, where no action is
// scored, so the refinement only learns values for the steps after it.
// Taken: one lookahead, from the state the assistant's action led to (the
// state the next step refines at). When such a step (or hear(), after the
// last action) also scores an utterance, a hypothesis whose plan from the
// state is already stored gets no more than that: the utterance is explained
// by that stored plan, which refining cannot change; the others get the full
// refinement. All: a refinement at every step (the paper's), a lookahead from every
// successor. With no search stopped by its budget the later Q-values are the
// same optimal costs either way (docs/decisions.md, "Refining the
// assistant's turns").
enum class AssistantTurns { Taken, All };
util::Choices<AssistantTurns>& assistant_turns_choices();
std::string to_string(AssistantTurns a);               // "taken", "all"
AssistantTurns parse_assistant_turns(const std::string& text);  // throws InputError

struct InferenceOptions {
  // Budgets of each A* search inside a refinement (the paper's: 2^18 nodes, no time limit).
  search::SearchOptions refine = [] {
    search::SearchOptions o;
    o.max_nodes = size_t{1} << 18;
    return o;
  }();
  // nullopt: the pack's (mDKG refines, VH does not: V = -h_g).
  std::optional<bool> search;
  std::string heuristic;  // empty: the pack's inference heuristic
  std::optional<TemperatureWeights> temperature_prior;  // empty: the pack's
  UtteranceModelOptions utterance;
  // Include the goal-independent log p_speak / log(1 - p_speak) factors (they
  // change only the log marginal likelihood, never a posterior).
  bool speak_factors = true;
  double p_speak = 0.05;
  // Which state explains an utterance annotated after k actions: After = s_k, the state the speaker was in when speaking,
  // with the policies refined at s_k (the paper's model; default); Before =
  // s_{k-1}, the reference code's alignment. docs/decisions.md has the reasons.
  UtteranceTiming utterance_timing = UtteranceTiming::After;
  // Refinement at the assistant's turns, where no action is scored (see AssistantTurns).
  AssistantTurns assistant_turns = AssistantTurns::Taken;
  // Utterances the model cannot read carry little evidence (docs/decisions.md,
  // "Unreadable utterances"): the utterance log-likelihoods are multiplied by
  // a weight from the share of readable words (1 at or above
  // readable_share_full, 0 at or below readable_share_none, linear between).
  // An utterance impossible under every hypothesis is ignored. Both are
  // reported in UtteranceRecord::warning. false: the model's scores as they are.
  bool temper_unreadable = true;
  // The utterance model's noise ε (domains::InferenceSettings::utterance_noise):
  // each hypothesis' utterance likelihood L_h enters as (1 - ε) L_h + ε B,
  // B the mean of L over the hypotheses scored (in particle mode, those held
  // when the utterance is first heard; later replays reuse that B). Under a
  // uniform prior this is the language posterior mixed with uniform at ε.
  // nullopt: the pack's.
  std::optional<double> utterance_noise;
  // The exponent τ of that robust likelihood (domains::InferenceSettings::
  // utterance_exponent): hypothesis h gains τ log((1 - ε) L_h + ε B).
  // nullopt: the pack's.
  std::optional<double> utterance_exponent;
  double readable_share_none = 0.25;
  double readable_share_full = 0.5;
  // Threads refining the hypotheses' policies in parallel (they are
  // independent, so results do not depend on it). 1: sequential (callers that
  // already run several inferences at once, like `clips bench`); 0: all cores.
  int threads = 1;
  // Particle approximation (see the top of this file and particle_belief.hpp).
  // 0: exact enumeration of every hypothesis (default).
  int particles = 0;
  double ess_threshold = 0.5;    // resample when ESS < ess_threshold × particles, in [0, 1]
  int rejuvenation_moves = 2;    // MH sweeps over goals after each resampling, >= 0
  // When else the sweeps run (particle_belief.hpp says why not only after resampling).
  Rejuvenation rejuvenate = Rejuvenation::Evidence;
  int proposal_groups = 8;       // independent exploring proposals per sweep (particle_belief.hpp), >= 1
  // Which modalities keep a filter of their own. All: one per modality (the
  // baselines' posteriors are as good as CLIPS's, but the hypotheses any of
  // them holds are refined). Clips: only the CLIPS (Both) modality; the
  // action-only and utterance-only posteriors are importance-reweighted from
  // its particles (weight × their likelihood / CLIPS's), which costs nothing
  // but misses hypotheses the CLIPS particles left.
  ParticleFilters particle_filters = ParticleFilters::All;
  // Reported posterior: exact weights on the hypotheses the particles hold
  // (Support) or the weighted particle counts (Weights); particle_belief.hpp.
  ParticleEstimate particle_estimate = ParticleEstimate::Support;
  uint64_t particle_seed = 1;    // results are a function of the seed (and not of `threads`)
};

// Throws InputError for option values no belief can run with (negative
// particle count, ESS threshold outside [0, 1], negative moves).
void check_options(const InferenceOptions& options);

struct Hypothesis {
  int goal = 0;     // index into Belief::goals()
  int profile = 0;  // index into Belief::profiles()
  std::shared_ptr<const model::Specification> spec;
};

// A step stopped by Belief::set_call_bounds' stop test before its work was
// done. The belief is then half-updated: callers run steps on a copy.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Normalised posteriors of one modality.
struct Posterior {
  std::vector<double> hypotheses;  // in Belief::hypotheses() order
  std::vector<double> goals;       // marginal over cost profiles
  std::vector<double> profiles;    // marginal over goals
  double log_marginal = 0;         // log Σ_h P(h) P(data | h)
};

struct UtteranceRecord {
  std::string text;
  std::vector<HypothesisUtterance> hypotheses;  // likelihood and per-command posterior per hypothesis
  // How much of the text the model can read (lm/readability.hpp), and the
  // weight its log-likelihoods entered the belief with: 1 for readable text,
  // less for text the model mostly cannot read, 0 when ignored.
  double readable_share = 1;
  double evidence_weight = 1;
  // log B, the noise component of the robust likelihood (see
  // InferenceOptions::utterance_noise); -inf when it is off.
  double log_background = -std::numeric_limits<double>::infinity();
  std::string warning;  // non-empty when the weight is below 1: why, for the user
};

// The weight an utterance's log-likelihoods get from its readable share.
double evidence_weight(double readable_share, const InferenceOptions& options);
// log B of InferenceOptions::utterance_noise: the log of the mean likelihood
// over the scored hypotheses (NaN ones, not scored, left out); -inf when
// `noise` is 0 or nothing was scored.
double log_background(const std::vector<HypothesisUtterance>& hypotheses, double noise);

// What one step observed and the belief after it (a Gen-style trace entry).
struct StepRecord {
  int t = 0;                 // 0: initialisation at s_0
  std::string action;        // a_t; empty at t = 0
  bool evidence = false;     // a_t is a human action (robot actions are interventions)
  std::array<Posterior, 3> posterior;  // indexed by Modality
  std::vector<UtteranceRecord> utterances;
  double seconds = 0;        // wall time of this step
  // Its work summed over the refinement threads: the step's time on one
  // thread (equal to `seconds` when the hypotheses are refined sequentially).
  double work_seconds = 0;
  const Posterior& operator[](Modality m) const { return posterior[static_cast<int>(m)]; }
};

class Belief {
 public:
  Belief(std::shared_ptr<const pddl::Task> task, domains::PackPtr pack, std::vector<data::GoalSpec> goals,
         std::vector<model::CostProfile> profiles, InferenceOptions options = {});

  // INIT (step 0): fresh policies refined at s0; utterances spoken before any
  // action are scored there. `lm` may be null when there are no utterances.
  StepRecord start(const pddl::State& s0, const std::vector<std::string>& utterances = {},
                   lm::LanguageModel* lm = nullptr);
  // Step t: a_t taken in `state` (= s_{t-1}): refine there, score a_t if it is
  // the human's, score the utterances annotated at t in `state`, then move to
  // s_t = apply(a_t, state). Without utterances this is the "speak = false"
  // step used by online assistance.
  StepRecord observe(pddl::ActionId action, const pddl::State& state, const std::vector<std::string>& utterances = {},
                     lm::LanguageModel* lm = nullptr);
  // Same, at the current state.
  StepRecord observe(pddl::ActionId action) { return observe(action, state_, {}, nullptr); }
  // Utterances heard in the current state s_t after the last step (the
  // "after" timing): refine at s_t, score them there. Returns `last` (the
  // record of the step that led to s_t) with the posteriors updated and the
  // utterances added; the speak factor of that step becomes log p_speak.
  StepRecord hear(const std::vector<std::string>& utterances, lm::LanguageModel& lm, StepRecord last);

  Posterior posterior(Modality m) const;

  const pddl::Task& task() const { return *task_; }
  const domains::Pack& pack() const { return *pack_; }
  const domains::PackPtr& pack_ptr() const { return pack_; }
  const std::vector<data::GoalSpec>& goals() const { return goals_; }
  const std::vector<model::CostProfile>& profiles() const { return profiles_; }
  const std::vector<Hypothesis>& hypotheses() const { return hyps_; }
  // π_h after the last step; search::Policy is a copyable value for assistance
  // (copies share the heuristic object, which each refine re-prepares).
  const std::vector<search::Policy>& policies() const { return policies_; }
  // The hypothesis of h's goal under the base profile of h's alone twin
  // profile (model::CostProfile::twin_of), or h itself: whose plans h's words
  // come from, and whose costs the assistant values h with.
  int base_of(size_t h) const { return base_of_[h]; }
  // Lookahead searches so far that ended at their node or time budget (see
  // search::RefineStats): non-zero means the posterior depends on the budget.
  size_t searches_stopped_by_budget() const;
  std::vector<search::Policy>& policies() { return policies_; }
  const TemperatureBelief& temperature(int h) const { return temps_[h]; }
  double action_log_likelihood(int h) const { return action_ll_[h]; }
  double utterance_log_likelihood(int h) const { return utterance_ll_[h]; }
  const pddl::State& state() const { return state_; }  // s_t
  int t() const { return t_; }
  const UtteranceModel& utterance_model() const { return *utterance_model_; }
  bool searches() const { return search_; }

  // Particle mode (InferenceOptions::particles > 0).
  bool particle_mode() const { return !filters_.empty(); }
  // The modality's filter counters; null in exact mode, for a modality
  // without a filter of its own (ParticleFilters::Clips), or for the
  // utterance modality before the first utterance (its posterior is the prior
  // until then, so it has no particles yet).
  const ParticleStats* particle_stats(Modality m) const;
  // Hypotheses with non-zero weight in the modality (all, in exact mode).
  std::vector<int> support(Modality m) const;
  // Whether hypothesis h has processed the whole history (always in exact mode).
  bool current(int h) const { return !particle_mode() || cursor_[h] == history_.size(); }
  // Brings the policies of every hypothesis with non-zero weight in `m` up to
  // the present (a no-op in exact mode, and for all modalities but the
  // utterance one before its first utterance: there every hypothesis has the
  // prior weight and only some are current). Callers that read policies()
  // under such a posterior call it first.
  void sync_policies(Modality m);
  // The same for the given hypotheses.
  void sync_policies(const std::vector<int>& hs);
  // Bounds of the calls that follow (the session engine's per-call limits,
  // src/engine): every search ends at `deadline` (as SearchOptions::deadline),
  // and once `stop` returns true no further refinement starts and the step
  // throws Interrupted. time_point::max() and an empty `stop`: no bounds.
  void set_call_bounds(std::chrono::steady_clock::time_point deadline, std::function<bool()> stop) {
    options_.refine.deadline = deadline;
    stop_ = std::move(stop);
  }
  // Refinements of single hypotheses so far (the cost that particles save).
  size_t refinements() const { return refinements_; }
  // Threads the refinements of a step run on (1: sequential).
  int refine_threads() const { return pool_ ? pool_->threads() : 1; }

 private:
  // One recorded observation, replayed by hypotheses that join late.
  struct Event {
    enum class Kind { Refine, Act, Speak } kind = Kind::Refine;
    pddl::State state;
    pddl::ActionId action = -1;             // Act; Refine: >= 0 refines toward this action only
    bool keep_stored = false;               // Refine: as RefineWhat::keep_stored
    std::vector<std::string> texts{};       // Speak: as scored (deixis resolved)
    std::vector<std::string> said{};        // Speak: as heard
    std::vector<double> weights{};          // Speak: each text's evidence weight (set when first scored)
    std::vector<double> backgrounds{};      // Speak: each text's log B (set when first scored)
    double before = 0, after = 0;           // Speak: goal-independent log factors around the texts
  };
  // What a step refines at s.
  struct RefineWhat {
    // >= 0: Policy::refine_toward(s, toward) instead of refine_step(s).
    pddl::ActionId toward = -1;
    // A hypothesis whose policy already has a stored goal path from s is
    // refined only toward `toward` (not at all when it is -1); the others get
    // refine_step(s). For utterances at the assistant's turns: the utterance
    // is explained by the rollout from s, which follows the stored path, and
    // no refinement changes a stored path.
    bool keep_stored = false;
  };
  void refine_all(const pddl::State& s, RefineWhat what);
  void refine_some(const pddl::State& s, const std::vector<int>& hs, RefineWhat what);
  // What a step at s refines before `action` is taken.
  RefineWhat refine_what(pddl::ActionId action, bool evidence, const std::vector<std::string>& utterances) const;
  // What hear() refines at the current state before scoring its utterances.
  RefineWhat hear_refine_what() const;
  // log P(a | s, h) with h's policy as refined at s; updates h's temperatures.
  double score_action(int h, const pddl::State& s, pddl::ActionId action);
  // Particle mode: the Speak event of a step with these utterances; `step`:
  // the step's speak/no-speak factor (false for hear(), which corrects the
  // step's factor afterwards instead).
  Event speak_event(const pddl::State& s, const std::vector<std::string>& texts, bool step) const;
  // Particle mode: process events [cursor_[h], until) for every h in hs.
  void sync(const std::vector<int>& hs, size_t until);
  void apply_event(const Event& e, const std::vector<int>& hs);
  // Particle mode: the step's events are appended; bring the needed
  // hypotheses up to date, score the new utterances (the last event, if
  // `speak`), update the filters. Returns the utterance records.
  std::vector<UtteranceRecord> particle_step(lm::LanguageModel* lm);
  double modality_ll(Modality m, int h) const;
  // Whether m has a filter of its own (else its weights come from Both's particles).
  bool tracked(Modality m) const {
    return m == Modality::Both || options_.particle_filters == ParticleFilters::All;
  }
  // The filter whose particles carry m's posterior: m's own, or the CLIPS one.
  const ParticleFilter& filter_for(Modality m) const {
    return filters_[static_cast<int>(tracked(m) ? m : Modality::Both)];
  }
  // The log-likelihood that weighs m's particles: m's own, or for a modality
  // read off the CLIPS filter, m's likelihood where CLIPS's is not zero.
  double particle_ll(Modality m, int h) const;
  Posterior particle_posterior(Modality m) const;
  // The plans each hypothesis' speaker may have in mind at s (the utterance
  // model's rule; tie-breaking rollouts refine the policies, in parallel).
  // An alone twin (model::CostProfile::twin_of) speaks as its base: it
  // models how the principal acts, and a request for help says what the
  // joint plan would have the assistant do.
  std::vector<SpeakerPlans> speaker_plans(const pddl::State& s, const std::vector<int>& hs);
  // Each hypothesis' goal statement (UtteranceModel::goal_statement), or none
  // when the pack's language has goal_statements 0.
  std::vector<commands::Command> goal_statements(const pddl::State& s, const std::vector<int>& hs) const;
  // Scores `utterances` in s and adds them to the utterance part; with
  // speak_factor, also this step's goal-independent speak/no-speak factor.
  std::vector<UtteranceRecord> score_utterances(const pddl::State& s, const std::vector<std::string>& utterances,
                                                lm::LanguageModel* lm, bool speak_factor = true);
  StepRecord record(std::string action, bool evidence, std::vector<UtteranceRecord> utts, double seconds) const;
  // Sets the record's readable share, evidence weight and warning.
  void weigh_utterance(UtteranceRecord& rec) const;
  bool is_speaker_action(pddl::ActionId a) const;
  pddl::ObjectId acting_agent(const pddl::State& s) const;  // see refine_seconds_

  std::shared_ptr<const pddl::Task> task_;
  domains::PackPtr pack_;
  std::vector<data::GoalSpec> goals_;
  std::vector<model::CostProfile> profiles_;
  InferenceOptions options_;
  std::function<bool()> stop_;  // set_call_bounds
  bool search_ = true;
  double noise_ = 0;     // utterance noise ε (InferenceOptions::utterance_noise)
  double exponent_ = 1;  // τ (InferenceOptions::utterance_exponent)
  // What one hypothesis' utterance log-likelihood adds to its evidence: the
  // robust mixture (see utterance_noise) times τ.
  double utterance_evidence(double ll, double log_background) const;
  std::shared_ptr<const UtteranceModel> utterance_model_;
  std::vector<Hypothesis> hyps_;
  std::vector<int> base_of_;  // per hypothesis, base_of(h)
  // The delegating speakers (domains::InferenceSettings::speaker_delegates):
  // policies searched only to find what such a speaker would ask for, and
  // per hypothesis the index of its own (-1: it speaks as another).
  std::vector<search::Policy> delegates_;
  std::vector<int> delegate_of_;
  double delegate_share_ = 0;
  // The request reading's share (domains::InferenceSettings::request_plans;
  // 0: off) and the heuristic its plans search with.
  double request_share_ = 0;
  std::string heuristic_name_;
  // The share of the speaker model's plans that spare the principal's own
  // effort (sparing_plan); 0: none.
  double spare_share_ = 0;
  // The joint plan of hypothesis h from s in which the principal's own
  // actions (not its no-op) cost kSparingFactor times as much: the assistant
  // does all it can, the principal only what the assistant cannot. Empty
  // when the search finds none within its budget.
  SpeakerPlans sparing_plan(size_t h, const pddl::State& s);
  // The speaker model and the request reading both ask for it in the state an
  // utterance is heard in: each hypothesis' plan is searched once per state.
  struct SparingMemo {
    std::mutex mu;
    pddl::State state;
    std::map<size_t, SpeakerPlans> plans;
  };
  std::shared_ptr<SparingMemo> sparing_memo_ = std::make_shared<SparingMemo>();
  // One A* plan (the pack's heuristic, at most 2^16 nodes) for `spec` from s.
  SpeakerPlans plan_for(const model::Specification& spec, const pddl::State& s);
  // Its variant in which the principal keeps the goal's last steps: the
  // kinds of action (schemas) that make a goal atom true cost the principal
  // what they cost, and the assistant kSparingFactor times as much. So the
  // assistant fetches and hands over, and the principal puts ("bring me the
  // jar"). Empty where `sparing` (sparing_plan's) leaves those steps to the
  // principal already, or when none is found.
  SpeakerPlans handing_plan(size_t h, const pddl::State& s, const SpeakerPlan& sparing);
  // Adds HypothesisUtterance::requests to `scores` (per utterance, per
  // hypothesis) of `texts` heard in s.
  void read_requests(const pddl::State& s, const std::vector<std::string>& texts,
                     std::vector<std::vector<HypothesisUtterance>>& scores, lm::LanguageModel& lm);
  std::shared_ptr<search::StateGraph> graph_;  // shared by the policies (null without search)
  std::vector<search::Policy> policies_;
  std::vector<TemperatureBelief> temps_;
  // The progress share of the action likelihood
  // (domains::InferenceSettings::progress_share) and, per hypothesis, made
  // when first needed, its goal as the principal alone would reach it.
  double progress_share_ = 0;
  struct Progress;
  std::vector<std::shared_ptr<Progress>> progress_;
  // Progress(action) among the principal's `candidates` in s under h.
  double progress_likelihood(int h, const pddl::State& s, const std::vector<pddl::ActionId>& candidates,
                             pddl::ActionId action);
  std::vector<double> log_prior_, action_ll_, utterance_ll_;
  pddl::State state_;
  int t_ = 0;
  pddl::ObjectId speaker_ = -1;
  // The kind of the object the speaker last acted on (a salient action's
  // focal object): what "one more of these" names (language/deixis.hpp).
  std::string deictic_type_;
  pddl::ObjectId deictic_object_ = -1;  // that object itself: "one more" means another one
  // Notes the speaker's action for deictic_type_.
  void note_deixis(pddl::ActionId action);
  // The utterances as the language model reads them in s (deixis resolved).
  std::vector<std::string> resolved(const std::vector<std::string>& utterances, const pddl::State& s) const;
  std::shared_ptr<util::WorkerPool> pool_;  // null when refining sequentially
  // Scheduling only: per acting agent (the first argument of the state's
  // first applicable action, -1 if none), each hypothesis' last refinement time.
  std::map<pddl::ObjectId, std::vector<double>> refine_seconds_;
  // Refinement time the worker pool saved in the current step (the sum of
  // its refinements' times minus its wall time), for StepRecord::work_seconds.
  double parallel_saved_ = 0;
  std::vector<size_t> budget_stops_;        // per hypothesis (one writer each, also when threaded)
  size_t refinements_ = 0;
  // Particle mode only.
  std::vector<Event> history_;
  std::vector<size_t> cursor_;               // per hypothesis: events processed
  std::vector<ParticleFilter> filters_;      // indexed by Modality; [UtteranceOnly] unused until `heard_`
  bool heard_ = false;                       // an utterance has been observed
  double speak_ll_ = 0;                      // goal-independent factors so far (the utterance modality's prior-only marginal)
  // The language model of the last utterance, kept to replay utterance
  // events for hypotheses that join later (it must outlive the belief's
  // updates; callers keep one per run).
  lm::LanguageModel* lm_ = nullptr;
};

// Inference over one dataset plan (engine::run_inference drives the engine
// over it): INIT at s_0, then one step per observed action; utterances with
// index k are scored at s_k (default) or s_{k-1}
// (InferenceOptions::utterance_timing); index 0 at s_0.
struct InferenceRun {
  std::string plan_id;
  std::vector<std::string> goals;     // labels
  int true_goal = -1;
  std::vector<std::string> profiles;  // names
  int true_profile = 0;
  std::vector<StepRecord> steps;      // steps[0]: after INIT; steps[t]: after a_t
  std::shared_ptr<Belief> belief;     // the belief after the last step (policies for assistance)
  double seconds = 0;
  size_t searches_stopped_by_budget = 0;  // over the whole run (Belief::searches_stopped_by_budget)
  // The warnings of utterances that carried reduced or no evidence, in order.
  std::vector<std::string> utterance_warnings;

  const std::vector<search::Policy>& policies() const { return belief->policies(); }
  const Posterior& final_posterior(Modality m) const { return steps.back()[m]; }
  double p_true_goal(Modality m) const { return final_posterior(m).goals.at(true_goal); }
};

}  // namespace clips::inference
