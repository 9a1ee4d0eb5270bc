#pragma once
// Assistance: given a belief over goal
// specifications (weights + their RTAA* policies), the assistant acts in the
// shared world while a simulated human principal pursues the true goal.
//
//   Hypothesis        weight + specification + policy (copied, then refined)
//   AssistSetup       the world: task, start state s_T, the observed length T,
//                     horizon, who is principal/assistant, the completed plan
//                     the principal follows, and what counts as an option
//   AssistResult      executed joint plan, success, length, costs, options
//
// Episodes: a decision policy (Q_MDP, pi-bar or any registered one) decides
// each assistant turn, on the posterior fixed after the observed prefix
// (offline) or updated after every action through an OnlineBelief (online);
// and the paper's pi-bar_MDP evaluation (exact expectation over hypotheses).
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/language_config.hpp"
#include "model/turns.hpp"
#include "search/rtaa.hpp"
#include "util/choices.hpp"

namespace clips::assist {

// A command the principal may have meant by their last instruction, under
// one hypothesis, as ground actions: the assistant's part (what it was asked
// to do) and the principal's own (what they said they would do themselves).
struct RequestedCommand {
  double probability = 0;  // P(c | u, s, h)
  std::string text;        // display form, for explanations
  std::vector<pddl::ActionId> assistant_part, principal_part;
};
using Request = std::vector<RequestedCommand>;

struct Hypothesis {
  Hypothesis() = default;
  Hypothesis(double w, std::shared_ptr<search::Policy> p, std::shared_ptr<const Request> r = nullptr)
      : weight(w), policy(std::move(p)), request(std::move(r)) {}
  double weight = 0;
  std::shared_ptr<search::Policy> policy;  // owns its specification
  // What this hypothesis says the last instruction asked for (null: none
  // heard, or a method that does not listen).
  std::shared_ptr<const Request> request;
};

// How Q_MDP picks among the assistant's actions of equal expected value
// (within AssistSetup::tie_tolerance of the best).
//   Paper:   the paper's rule: the hypotheses' common best action when
//            they all agree, else the first maximiser in action order.
//   Request: the action whose continuation carries out most of what the
//            principal most probably asked for (P(c | u, observations),
//            summed over hypotheses) and takes over least of what they said
//            they would do themselves; the paper's choice when that is equal.
// docs/decisions.md ("Following the request") has the numbers.
enum class AssistRule { Paper, Request };
util::Choices<AssistRule>& assist_rule_choices();
std::string to_string(AssistRule r);              // "paper", "request"
AssistRule parse_assist_rule(const std::string& text);  // throws InputError

// How Q_MDP bounds a hypothesis' Q-values before weighting them.
// The paper's rule is max(Q, -((horizon - t) * cost(wait) + cost(a))), meant
// to replace dead ends (-inf) by the cost of waiting until the
// horizon. Taken literally it also floors FINITE values: a hypothesis whose
// goal costs more than waiting out the horizon then prefers waiting, and the
// assistant procrastinates although its goal is reachable.
//   DeadEnds: only -inf is replaced (the stated purpose; default).
//   Horizon:  the formula as written (the reference code).
// docs/decisions.md has the reasons.
enum class QaFloor { DeadEnds, Horizon };
util::Choices<QaFloor>& qa_floor_choices();
std::string to_string(QaFloor f);         // "dead-ends", "horizon"
QaFloor parse_qa_floor(const std::string& text);  // throws InputError

// The turn-taking names (principal: the simulated human, assistant, their
// no-op action and turn predicate) are the pack's (model::TurnTaking).
struct AssistSetup : model::TurnTaking {
  std::shared_ptr<const pddl::Task> task;
  pddl::State start;                 // s_T
  int observed_steps = 0;            // T
  int horizon = 100;                 // model timesteps T+1 .. horizon
  double noop_cost = 0.6;            // padding step cost (mean wait cost)
  // Hypotheses below are ignored by Q_MDP and pi-bar; the cut-off used is at
  // most half the largest weight, so a flat posterior over many goals still
  // has hypotheses to decide on.
  double weight_threshold = 0.02;
  QaFloor qa_floor = QaFloor::DeadEnds;
  std::vector<pddl::ActionId> completed;  // the ground-truth continuation from s_T
  // The assistance option an action realises, if any (e.g. a key the robot
  // picks up in a keys plan).
  std::function<std::optional<std::string>(pddl::ActionId)> option_of;
  search::SearchOptions refine_options;   // 2^16 nodes, 10 s per search by default
  // False where the pack's model reads values off the heuristic itself
  // (V = -h_g, no search), so policies are read but never refined.
  bool refine = true;
  // A pack rule: the principal also takes the k-th completed-plan action when it
  // is legal in the current state, even off the completed trajectory.
  bool follow_plan_by_index = false;
  AssistRule rule = AssistRule::Request;
  // The simulated principal does not wait for ever: at a turn where nothing
  // changed since its last one (both agents waited), it plans as if the
  // assistant were frozen, i.e. does the work itself. Without it a principal
  // whose joint plan has the assistant fetch something the assistant does not
  // believe in, and an assistant that waits for the principal, wait until the
  // horizon. Set with the request rule (the paper's simulations do not).
  bool impatient_principal = true;
  // Its counterpart: the assistant does not answer a round in which both
  // agents waited with another wait (it takes its best other action), since
  // a principal who waits on the assistant and an assistant that waits on the
  // principal never move again. Set with the request rule.
  bool restless_assistant = true;
  // The simulated principal's trust: an assistant action that its own
  // recorded continuation takes in that state (the completed plan's next
  // step, where the state is on its trajectory) never counts against the
  // assistant. The recording is the principal's own plan with what it asked
  // the assistant to do, which need not be the cheapest joint plan (a fetch
  // the principal could have made itself). Set with the request rule.
  bool trusts_own_plan = true;
  // Actions whose expected value is within this share of the cheapest
  // candidate action's cost of the best are tied. Exact ties are common
  // wherever two plans cost the same; the tolerance also lets the assistant
  // do what it was asked when unlikely goals make another action look a
  // little better (a quarter of an action, in expectation).
  double tie_tolerance = 0.25;
  // Per action schema: the 0-based argument positions of the acting agent and
  // the focal object of a salient action (commands are matched on them), or
  // {-1, -1} for schemas people do not ask for. Empty: no request is read.
  std::vector<std::pair<int, int>> salient_args;
  // The values of the options a library user registered (clips::register_option),
  // for a registered decision policy to read.
  std::map<std::string, std::string> registered_options;
  AssistSetup() {
    refine_options.max_nodes = 1u << 16;
    refine_options.max_seconds = 10;
  }
  const model::TurnTaking& turns() const { return *this; }
  void set_turns(const model::TurnTaking& t) { static_cast<model::TurnTaking&>(*this) = t; }
};

struct AssistResult {
  std::vector<pddl::ActionId> plan;       // the run's executed actions (mean run: most likely)
  int noops = 0;                          // padding steps after a failure
  bool goal_reached = false;
  double plan_length = 0;                 // expected for stochastic methods
  double plan_cost = 0;                   // under the true specification
  double human_cost = 0;
  double success = 0;                     // probability of reaching the goal
  std::map<std::string, double> options;  // option -> probability
  std::vector<double> decision_seconds;   // wall time of each assistant decision (Q_MDP)
  // Q_MDP with the request rule: each decision it made, in order: where it
  // carried out what was asked, the reason (Decision::reason); where several
  // actions tied, the tied actions with their values and request scores, the
  // action taken and the command that broke the tie (`clips assist --explain`).
  std::vector<std::string> ties;
};

// Belief that keeps updating during online assistance (implemented by the
// inference stage).
class OnlineBelief {
 public:
  virtual ~OnlineBelief() = default;
  // Called after the action `a` was taken in `pre` (assistant actions are
  // interventions: they advance the state but carry no evidence).
  virtual void observe(const pddl::State& pre, pddl::ActionId a) = 0;
  virtual std::vector<Hypothesis>& hypotheses() = 0;
};

struct Decision;
struct DecisionInput;
// A decision policy: the assistant's action from what one decision sees. The
// live sessions' policies are registered with theirs (engine/policies.hpp);
// the simulated episodes below call the same one at every assistant turn.
using Decide = std::function<Decision(const DecisionInput&)>;

// Simulated episodes in which the assistant decides by `decide` at each of
// its turns: on the posterior after the observed prefix, kept for the whole
// episode (offline, the paper's Q_MDP evaluation), or on a belief updated by
// each action of the episode (online). The simulated principal's
// plan-following rule needs the true hypothesis.
AssistResult offline_episode(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis,
                             const Decide& decide);
AssistResult online_episode(const AssistSetup& setup, OnlineBelief& belief,
                            std::shared_ptr<const model::Specification> true_spec,
                            std::shared_ptr<heuristics::Heuristic> true_heuristic, const Decide& decide);
// offline_episode deciding by qmdp_decision.
AssistResult qmdp_offline(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis);
// The paper's pi-bar_MDP evaluation: not one episode but the expectation over
// the hypotheses above the threshold of the episode the assistant would have
// had with that hypothesis alone (its greedy policy), the world frozen once
// the principal stops trusting it (spec 9.5).
AssistResult pibar_mdp(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis);
// An assistant that plays a script of `length` actions (the multimodal
// baseline's): `play(s, i)` is its action for entry i on its next turn (a
// wait for an entry it cannot play). The principal is the simulated one of
// the episodes above, trusting the script to its end and then finishing
// alone, the assistant frozen.
AssistResult scripted_episode(const AssistSetup& setup, search::Policy truth, size_t length,
                              const std::function<pddl::ActionId(const pddl::State&, size_t)>& play);

// Whether `s` is the assistant's turn (the principal is not the active agent).
bool assistant_turn(const AssistSetup& setup, const pddl::State& s);
// One assistant decision in state s at model timestep t, for callers that
// drive the episode themselves (clips::Session, clips serve, `assist
// --problem`). The simulated episodes decide by the same rule. The hypotheses'
// policies are refined at s (setup.refine), as the simulated episodes do.
struct Decision {
  pddl::ActionId action = -1;
  std::vector<pddl::ActionId> candidates;  // the active agent's applicable actions
  // Per candidate. Q_MDP: the weighted, floored Q-value; pi-bar: the
  // probability that the policy mixture takes it.
  std::vector<double> values;
  // Every hypothesis above the weight threshold has the same best action
  // (Q_MDP then takes it whatever the weighted values say).
  bool unanimous = false;
  // AssistRule::Request, when several actions tie at the best value: per
  // candidate, how much of the request its continuation carries out (NaN for
  // candidates outside the tie), and the most probable command behind the
  // choice when the request changed it.
  std::vector<double> request_scores;
  std::string request_command;
  bool broke_tie = false;
  // AssistRule::Request: the action is the first step of the assistant's plan
  // for what the live hypotheses most probably asked of it
  // (`request_command`), which `request_share` of the weight of the
  // readings that ask the assistant for something asks for.
  bool followed_request = false;
  double request_share = 0;
  // It gives the principal something that leaves them one more action of
  // their own (allowed: they asked for it).
  bool request_leaves_principal_a_step = false;
  // Why this action, in words: the rule that decided, with its numbers
  // (the same text for every front end and `clips assist --explain`).
  std::string reason;
};
// What one decision sees: the assistance set-up at the current state, the
// belief's hypotheses, the model time step, whether a round of waits just
// ended (round_of_waits) and the states since the last instruction (what was
// asked and done since is not asked again).
struct DecisionInput {
  const AssistSetup& setup;
  const std::vector<Hypothesis>& hypotheses;
  const pddl::State& state;
  int t = 0;
  bool stalled = false;
  const std::vector<pddl::State>* since_instruction = nullptr;
};
// The weight at or above which a hypothesis takes part in a decision: the
// setup's weight_threshold, at most half the largest weight. qmdp_decision and
// pibar_decision refine exactly these hypotheses (when setup.refine).
double live_threshold(const std::vector<Hypothesis>& belief, double threshold);
// The refinements a decision at s would make (when setup.refine), made now,
// with `between` called before each (a caller's cancellation check); then
// setup.refine is cleared so the decision does not make them again.
void refine_live(AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s,
                 const std::function<void()>& between = {});
// Whether the actions so far (oldest first) end in a round of waits: the
// assistant's no-op, then the principal's (AssistSetup::restless_assistant).
// The simulated episodes and the session engine both ask this.
bool round_of_waits(const AssistSetup& setup, const std::vector<pddl::ActionId>& actions);
// `stalled`: round_of_waits before this decision. `since_instruction`: the
// states since the last instruction was heard, before s (null: none kept); a
// request that held in one of them was done, and is not done again.
Decision qmdp_decision(const AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s, int t,
                       bool stalled = false, const std::vector<pddl::State>* since_instruction = nullptr);
// The salient-argument table of AssistSetup::salient_args for a command language.
std::vector<std::pair<int, int>> salient_argument_table(const pddl::Task& task, const commands::LanguageConfig& config);
// pi-bar_MDP's action: the mode of the mixture of the hypotheses' greedy
// policies (each hypothesis above the threshold votes with its weight).
Decision pibar_decision(const AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s);

// Metrics shared by every method.
double plan_cost(const model::Specification& spec, const std::vector<pddl::ActionId>& plan);
double human_cost(const model::Specification& spec, const std::vector<pddl::ActionId>& plan,
                  const std::string& principal);

}  // namespace clips::assist
