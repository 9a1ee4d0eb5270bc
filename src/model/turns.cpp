#include "model/turns.hpp"

#include "util/error.hpp"

namespace clips::model {

std::optional<pddl::ActionId> TurnTaking::find_noop(const pddl::Task& task, const std::string& agent) const {
  const int schema = task.domain().find_action(noop_action);
  const auto o = task.find_object(agent);
  if (schema < 0 || !o) return std::nullopt;
  return task.find_action(schema, {*o});
}

pddl::ActionId TurnTaking::noop(const pddl::Task& task, const std::string& agent) const {
  if (auto a = find_noop(task, agent)) return *a;
  const std::string action = "(" + noop_action + " " + agent + ")";
  if (task.domain().find_action(noop_action) < 0)
    throw InputError("the domain has no action '" + noop_action + "' (roles.noop_action), so " + agent +
                     " cannot do nothing: add it, or name the domain's no-op in the pack");
  if (!task.find_object(agent)) throw InputError("no object '" + agent + "' in this problem, so no " + action);
  throw InputError("no ground action " + action + " in this problem (roles.noop_action '" + noop_action +
                   "' must take the agent as its only parameter)");
}

pddl::Task::AtomRef TurnTaking::turn_atom(const pddl::Task& task, const std::string& agent) const {
  if (!task.domain().find_predicate(turn_predicate))
    throw InputError("the domain has no turn predicate '" + turn_predicate + "' (roles.turn_predicate)");
  return task.atom(turn_predicate, {agent});
}

bool TurnTaking::is_turn_of(const pddl::Task& task, const pddl::State& s, const std::string& agent) const {
  return task.test(s, turn_atom(task, agent));
}

const std::string& TurnTaking::active_agent(const pddl::Task& task, const pddl::State& s) const {
  return is_turn_of(task, s, principal) ? principal : assistant;
}

}  // namespace clips::model
