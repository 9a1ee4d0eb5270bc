#include "model/spec.hpp"

#include <algorithm>

namespace clips::model {

double CostProfile::cost(const std::string& agent, const std::string& action) const {
  auto it = costs.find({agent, action});
  return it == costs.end() ? default_cost : it->second;
}

CostProfile dkg_profile(int index) {
  if (index < 1 || index > 4) throw InputError("cost profile must be 1..4 (C1..C4), got " + std::to_string(index));
  CostProfile p;
  p.name = "C" + std::to_string(index);
  bool human_twice = index == 2 || index == 4;   // C2, C4: other human actions cost 2
  bool robot_unlock5 = index == 3 || index == 4; // C3, C4: robot unlocking costs 5
  double h = human_twice ? 2.0 : 1.0;
  for (const char* a : {"up", "down", "left", "right", "unlock", "handover"}) p.costs[{"human", a}] = h;
  p.costs[{"human", "pickup"}] = 5.0;
  p.costs[{"human", "wait"}] = 0.6;
  for (const char* a : {"up", "down", "left", "right", "pickup", "handover"}) p.costs[{"robot", a}] = 1.0;
  p.costs[{"robot", "unlock"}] = robot_unlock5 ? 5.0 : 1.0;
  p.costs[{"robot", "wait"}] = 0.6;
  return p;
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
  if (profile_.default_cost < 0 && !task_->domain().total_cost)
    throw InputError("cost profile 'task' needs the domain's own action costs, but domain '" +
                     task_->domain().name + "' (" + task_->domain().file +
                     ") declares no (total-cost) function: use unit costs instead");
  action_cost_.resize(task_->num_actions());
  for (pddl::ActionId a = 0; a < task_->num_actions(); ++a) {
    const auto& ga = task_->action(a);
    if (profile_.default_cost < 0) {
      action_cost_[a] = ga.cost;
      continue;
    }
    const std::string& name = task_->domain().actions[ga.schema].name;
    std::string agent = ga.args.empty() ? "" : task_->object_name(ga.args[0]);
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

}  // namespace clips::model
