#pragma once
// A goal specification = a goal condition + a cost profile (SymbolicPlanners'
// "specification"): "reach (has human gem2) minimising these action costs".
//
// CostProfile   per-agent, per-action-name costs, e.g. human pickup 5, robot
//               pickup 1, wait 0.6 (the agent is an action's first argument).
// Specification binds a goal and a profile to one grounded Task: the goal is
//               compiled once and every ground action gets its cost.
// Agents are frozen (may only wait / hand over) by setting `(frozen agent)` in
// the start state; see freeze() below.
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pddl/task.hpp"

namespace clips::model {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct CostProfile {
  std::string name;                                         // e.g. "C1"
  std::map<std::pair<std::string, std::string>, double> costs;  // (agent, action) -> cost
  double default_cost = 1.0;                                // anything not listed
  // Every action of `scaled_agent` except `unscaled_action` costs
  // `agent_factor` times what the rules above say: the twin of a profile in
  // which the principal plans as if the assistant did little (alone_twin).
  std::string scaled_agent;
  std::string unscaled_action;
  double agent_factor = 1.0;
  // Kept by every copy, the twin's too: each listed agent's actions except
  // its no-op (`noop_action`) cost the factor times as much. The principal's
  // effort valued above the assistant's (Pack::default_profile).
  std::map<std::string, double> effort_factors;
  std::string noop_action;
  // Per (agent, action): a factor on top of the others (a speaker who keeps
  // the goal's last steps for themselves: Belief::handing_plan).
  std::map<std::pair<std::string, std::string>, double> action_factors;
  // The index, in its profile set, of the profile this one is the alone twin
  // of (-1: none). The assistant values such hypotheses with that profile:
  // the twin models how the principal chooses, not what help costs.
  int twin_of = -1;
  double cost(const std::string& agent, const std::string& action) const;
  // The factor on a listed cost of `agent`'s `action`.
  double factor(const std::string& agent, const std::string& action) const;
};

// What an alone twin's name adds to its base's.
inline constexpr const char* kAloneSuffix = "-alone";

// The alone twin of profile `base` (at index `base_index` of its set): named
// "<name>-alone", with every action of `assistant` but its no-op `noop`
// costing `factor` times as much.
CostProfile alone_twin(const CostProfile& base, int base_index, const std::string& assistant,
                       const std::string& noop, double factor);
// A copy of `base` named `name` in which every action of `assistant` but its
// no-op `noop` costs `factor` times as much (not a twin: twin_of -1).
CostProfile scaled_assistant(const CostProfile& base, std::string name, const std::string& assistant,
                             const std::string& noop, double factor);
// Points each twin of `profiles` ("<name>-alone") at its base when the base is
// in the set too; a twin without its base keeps twin_of -1 (it speaks, and
// the assistant values it, as itself).
void link_alone_twins(std::vector<CostProfile>& profiles);

// Unit costs for every action (domains whose pack names no cost rules).
CostProfile unit_profile();
// Costs from the task itself: the problem's :metric, else its (increase (total-cost) n) effects.
CostProfile task_costs_profile();

class Specification {
 public:
  // `source` names the goal text in error locations (e.g. the file it came from).
  Specification(std::shared_ptr<const pddl::Task> task, std::string goal_text, CostProfile costs,
                const std::string& source = "<goal>");

  const pddl::Task& task() const { return *task_; }
  std::shared_ptr<const pddl::Task> task_ptr() const { return task_; }
  const std::string& goal_text() const { return goal_text_; }
  const pddl::CompiledCondition& goal() const { return goal_; }
  const CostProfile& profile() const { return profile_; }
  double cost(pddl::ActionId a) const { return action_cost_[a]; }
  bool is_goal(const uint64_t* s) const { return goal_.eval(s); }
  bool is_goal(const pddl::State& s) const { return goal_.holds(s); }
  // Minimum cost over all actions with this name (any agent), +inf if none.
  double min_cost(const std::string& action_name) const;
  // A stable key for caches: goal text + profile name.
  std::string key() const { return goal_text_ + " | " + profile_.name; }

 private:
  std::shared_ptr<const pddl::Task> task_;
  std::string goal_text_;
  pddl::CompiledCondition goal_;  // owned here: compiling it leaves the task untouched
  CostProfile profile_;
  std::vector<double> action_cost_;
};

// Returns a copy of `s` with `(frozen agent)` set (the agent may only wait or
// hand over what it holds). Throws if the task has no such predicate.
pddl::State freeze(const pddl::Task& task, const pddl::State& s, const std::string& agent);
// Whether freeze() can freeze `agent` in this task; s with `agent` free again.
bool can_freeze(const pddl::Task& task, const std::string& agent);
pddl::State unfreeze(const pddl::Task& task, const pddl::State& s, const std::string& agent);

}  // namespace clips::model
