#include "assist/setup.hpp"

#include "assist/request.hpp"

namespace clips::assist {

AssistSetup setup_for(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                      const inference::Belief& belief, std::optional<AssistRule> rule) {
  const domains::Roles& roles = pack.roles();
  AssistSetup setup;
  setup.task = std::move(task);
  setup.start = belief.state();
  setup.observed_steps = belief.t();
  setup.horizon = roles.horizon;
  setup.set_turns(roles);
  setup.noop_cost = roles.noop_cost;
  setup.refine = belief.searches();
  set_request_rule(setup, rule.value_or(parse_assist_rule(pack.spec().assistance_rule)), pack.language());
  return setup;
}

}  // namespace clips::assist
