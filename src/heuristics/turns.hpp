#pragma once
// The turn structure of a task written with the turn idiom of clips' domains:
// every action names its agent first, requires that agent's turn atom (e.g.
// (active human)), deletes it and adds exactly one other agent's turn atom
// (the static (next-turn ?a ?b) relation, folded at grounding). Read from the
// grounded actions; `ok` is false for any task that does not follow it.
#include <vector>

#include "pddl/task.hpp"

namespace clips::heuristics {

struct TurnStructure {
  bool ok = false;
  std::vector<pddl::ObjectId> agents;  // in order of first appearance
  std::vector<int> agent_of;           // per action: index into agents
  std::vector<int> turn_bit;           // per agent: its turn atom
  std::vector<int> next;               // per agent: the agent whose turn follows
  static TurnStructure of(const pddl::Task& task);
  // The agent whose turn it is in s, or -1.
  int active(const uint64_t* s) const;
};

}  // namespace clips::heuristics
