#pragma once
// Literal-listener assistance.
// The listener ranks commands for the literal utterance; m = 10 commands are
// drawn by systematic sampling; each is carried out by two-phase planning:
//   phase 1  A* for the command's goal (joint plan; retried with the human
//            frozen), phase 2  A* for the true goal with the robot frozen.
// Efficient: plan for the lifted (existential) command directly. Naive: plan
// for up to 10 random groundings of it whose last action is not statically
// impossible, options spread over all groundings.
#include <functional>
#include <memory>
#include <random>

#include "assist/assist.hpp"
#include "language/listener.hpp"

namespace clips::assist {

struct LiteralSetup {
  AssistSetup world;                                   // task, s_T, T, horizon, agents, option_of
  std::shared_ptr<const model::Specification> truth;   // true goal, true costs
  commands::LanguageConfig config;
  // Fresh heuristic per planning call (the domain's model heuristic).
  std::function<std::shared_ptr<heuristics::Heuristic>()> make_heuristic;
  // Is this object an assistance option (a key in keys plans, a door in doors plans)?
  std::function<bool(const std::string&)> is_option;
  size_t max_nodes = 1u << 16;
  // Domain knowledge: goals that can never hold (their search can only fail).
  std::function<bool(const std::string&)> goal_unsatisfiable;
  int samples = 10;
  // The principal's own policy for the true goal (the inference policy of
  // the true hypothesis), for when phase 2's A* runs out of budget: the
  // principal then goes on as in the Q_MDP simulations, by its policy, the
  // assistant frozen (null: padding with no-ops, as the reference does).
  std::shared_ptr<const search::Policy> truth_policy;
  // Grounding search (naive): objects per type and the static facts they must satisfy.
  std::map<std::string, std::vector<std::string>> objects_by_type;
  std::vector<commands::Term> facts;
};

struct LiteralRun {
  AssistResult result;
  double command_success = 0;
};

// The literal listener's plan for a command's goal formula from `from`: a
// joint plan, else one found with the principal frozen (the assistant's part
// alone), as phase 1 plans it. The bench carries it out whole; the live
// engine takes its first step. Not Success: no plan within `options`.
struct CommandPlan {
  search::SearchStatus status = search::SearchStatus::Failure;
  std::vector<pddl::ActionId> plan;  // empty with Success: the command already holds
};
CommandPlan command_plan(const std::shared_ptr<const pddl::Task>& task, const std::string& command_goal,
                         const model::CostProfile& profile, const pddl::State& from, const std::string& principal,
                         const std::function<std::shared_ptr<heuristics::Heuristic>()>& make_heuristic,
                         const search::SearchOptions& options);

// Runs one listener variant; `naive` selects the naive listener. `seed`
// makes the systematic draw and the naive subsampling reproducible.
LiteralRun literal_assist(const LiteralSetup& setup, const language::ListenerResult& ranked, bool naive,
                          uint64_t seed);

}  // namespace clips::assist
