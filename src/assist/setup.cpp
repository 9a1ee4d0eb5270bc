#include "assist/setup.hpp"

#include <algorithm>

#include "assist/request.hpp"
#include "pddl/plan.hpp"

namespace clips::assist {

AssistSetup setup_for(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                      const inference::Belief& belief, const SetupOptions& options) {
  const domains::Roles& roles = pack.roles();
  AssistSetup setup;
  setup.task = std::move(task);
  setup.start = belief.state();
  setup.observed_steps = belief.t();
  setup.horizon = roles.horizon;
  setup.set_turns(roles);
  setup.noop_cost = roles.noop_cost;
  setup.refine = belief.searches();
  set_request_rule(setup, options.rule.value_or(parse_assist_rule(pack.spec().assistance_rule)), pack.language());
  setup.qa_floor = options.qa_floor;
  setup.registered_options = options.registered_options;
  if (options.max_nodes) setup.refine_options.max_nodes = *options.max_nodes;
  if (options.max_seconds) setup.refine_options.max_seconds = *options.max_seconds;
  setup.refine_options.deadline = options.deadline;
  if (options.max_steps) setup.horizon = std::min(setup.horizon, setup.observed_steps + *options.max_steps);
  return setup;
}

AssistSetup setup_for_plan(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                           const inference::Belief& belief, const data::PlanRecord& plan,
                           const SetupOptions& options) {
  SetupOptions base = options;
  base.max_steps.reset();  // counted from the plan's observed part, below
  AssistSetup setup = setup_for(pack, task, belief, base);
  setup.observed_steps = static_cast<int>(plan.observed.actions.size());
  setup.completed = pddl::simulate(*setup.task, setup.start, plan.completed).actions;
  setup.option_of = [&pack, task, tag = plan.tag](pddl::ActionId a) { return pack.option_of(*task, a, tag); };
  setup.follow_plan_by_index = pack.roles().principal_follows_completed_plan;
  if (options.max_steps) setup.horizon = std::min(setup.horizon, setup.observed_steps + *options.max_steps);
  return setup;
}

}  // namespace clips::assist
