#pragma once
// Who takes turns in a task, and how its domain says whose turn it is.
//
// A domain pack names the principal (the speaker), the assistant (the agent
// clips plays), the no-op action an agent takes when it does nothing (`wait`
// in the paper domains, `(wait robot)`) and the turn predicate that holds of
// the agent whose turn it is (`active`, `(active human)`). Whether the domain
// writes the turn idiom itself or clips compiles it in (domains/
// task_transform.hpp), the grounded task has both. Everything outside the
// packs asks this type instead of spelling the names: domains::Roles extends
// it, assist::AssistSetup carries one.
#include <optional>
#include <string>

#include "pddl/task.hpp"

namespace clips::model {

struct TurnTaking {
  std::string principal = "human";     // the speaker, whose goal is inferred
  std::string assistant = "robot";     // the agent clips plays
  std::string noop_action = "wait";    // what an agent does when it does nothing
  std::string turn_predicate = "active";  // (<turn_predicate> agent): it is that agent's turn

  // The ground no-op of `agent`, e.g. (wait robot): InputError naming the
  // action and the pack field when the task has none.
  pddl::ActionId noop(const pddl::Task& task, const std::string& agent) const;
  std::optional<pddl::ActionId> find_noop(const pddl::Task& task, const std::string& agent) const;
  // The turn atom of `agent`, e.g. (active robot): InputError when the task
  // has no such predicate or object.
  pddl::Task::AtomRef turn_atom(const pddl::Task& task, const std::string& agent) const;
  // Whether it is `agent`'s turn in `s`.
  bool is_turn_of(const pddl::Task& task, const pddl::State& s, const std::string& agent) const;
  // The principal when it is the principal's turn in `s`, else the assistant.
  const std::string& active_agent(const pddl::Task& task, const pddl::State& s) const;
};

}  // namespace clips::model
