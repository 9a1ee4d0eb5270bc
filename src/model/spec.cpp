#include "model/spec.hpp"

#include <algorithm>

namespace clips::model {

double CostProfile::cost(const std::string& agent, const std::string& action) const {
  auto it = costs.find({agent, action});
  const double c = it == costs.end() ? default_cost : it->second;
  return c * factor(agent, action);
}

double CostProfile::factor(const std::string& agent, const std::string& action) const {
  double f = agent == scaled_agent && action != unscaled_action ? agent_factor : 1.0;
  if (!effort_factors.empty() && action != noop_action)
    if (auto it = effort_factors.find(agent); it != effort_factors.end()) f *= it->second;
  if (!action_factors.empty())
    if (auto it = action_factors.find({agent, action}); it != action_factors.end()) f *= it->second;
  return f;
}

CostProfile scaled_assistant(const CostProfile& base, std::string name, const std::string& assistant,
                             const std::string& noop, double factor) {
  CostProfile p = base;
  p.name = std::move(name);
  p.scaled_agent = assistant;
  p.unscaled_action = noop;
  p.agent_factor = factor;
  p.twin_of = -1;
  return p;
}

CostProfile alone_twin(const CostProfile& base, int base_index, const std::string& assistant,
                       const std::string& noop, double factor) {
  CostProfile p = scaled_assistant(base, base.name + kAloneSuffix, assistant, noop, factor);
  p.twin_of = base_index;
  return p;
}

void link_alone_twins(std::vector<CostProfile>& profiles) {
  for (CostProfile& twin : profiles) {
    if (twin.scaled_agent.empty()) continue;
    twin.twin_of = -1;
    for (size_t b = 0; b < profiles.size(); ++b)
      if (profiles[b].scaled_agent.empty() && profiles[b].name + kAloneSuffix == twin.name) twin.twin_of = static_cast<int>(b);
  }
}

CostProfile unit_profile() {
  CostProfile p;
  p.name = "unit";
  return p;
}

CostProfile task_costs_profile() {
  CostProfile p;
  p.name = "task";
  p.default_cost = -1;  // marker: use the task's own costs
  return p;
}

Specification::Specification(std::shared_ptr<const pddl::Task> task, std::string goal_text, CostProfile costs,
                             const std::string& source)
    : task_(std::move(task)),
      goal_text_(std::move(goal_text)),
      goal_(task_->compile_text(goal_text_, source)),
      profile_(std::move(costs)) {
  if (profile_.default_cost < 0 && !task_->domain().total_cost && !task_->problem().metric)
    throw InputError("cost profile 'task' needs the domain's own action costs, but domain '" +
                     task_->domain().name + "' (" + task_->domain().file +
                     ") declares no (total-cost) function and the problem no :metric: use unit costs instead");
  action_cost_.resize(task_->num_actions());
  for (pddl::ActionId a = 0; a < task_->num_actions(); ++a) {
    const auto& ga = task_->action(a);
    const std::string& name = task_->domain().actions[ga.schema].name;
    std::string agent = ga.args.empty() ? "" : task_->object_name(ga.args[0]);
    if (profile_.default_cost < 0) {
      action_cost_[a] = ga.cost * profile_.factor(agent, name);
      continue;
    }
    action_cost_[a] = profile_.cost(agent, name);
  }
}

double Specification::min_cost(const std::string& action_name) const {
  double m = kInf;
  for (pddl::ActionId a = 0; a < task_->num_actions(); ++a)
    if (task_->domain().actions[task_->action(a).schema].name == action_name) m = std::min(m, action_cost_[a]);
  return m;
}

pddl::State freeze(const pddl::Task& task, const pddl::State& s, const std::string& agent) {
  auto ref = task.atom("frozen", {agent});
  if (ref.bit < 0) throw InputError("this task cannot freeze '" + agent + "' (no dynamic (frozen " + agent + ") atom)");
  pddl::State out = s;
  task.set(out, ref, true);
  return out;
}

bool can_freeze(const pddl::Task& task, const std::string& agent) { return task.atom("frozen", {agent}).bit >= 0; }

pddl::State unfreeze(const pddl::Task& task, const pddl::State& s, const std::string& agent) {
  pddl::State out = s;
  auto ref = task.atom("frozen", {agent});
  if (ref.bit >= 0) task.set(out, ref, false);
  return out;
}

}  // namespace clips::model
