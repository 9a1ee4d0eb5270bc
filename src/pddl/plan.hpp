#pragma once
// Plan files: one ground action per line, e.g. `(pickup robot key2)`; a line
// starting with `;` is an utterance spoken at that point of the plan. Its
// annotation index is the number of action lines before it. Blank lines are
// ignored and surrounding whitespace is stripped.
#include <optional>
#include <string>
#include <vector>

#include "pddl/task.hpp"

namespace clips::pddl {

struct PlanLine {
  std::string text;
  SourceLoc loc;
};

struct Utterance {
  std::string text;
  int index = 0;  // number of actions preceding it
  SourceLoc loc;
};

struct PlanFile {
  std::string path;
  std::vector<PlanLine> actions;
  std::vector<Utterance> utterances;
};

PlanFile parse_plan(const std::string& text, const std::string& path);
PlanFile load_plan(const std::string& path);

// Resolves one action term to a ground action applicable in `s`; throws
// InputError naming the line and the reason (unknown action or object, arity,
// type, or the precondition that is false).
ActionId resolve_step(const Task& task, const PlanLine& line, const State& s);

struct Simulation {
  std::vector<ActionId> actions;
  std::vector<State> states;  // states[0] = start, states[i] = after i actions
  double cost = 0;            // sum of the task's own action costs
};

// Simulates every action from `start`; throws InputError at the first bad step.
Simulation simulate(const Task& task, const State& start, const PlanFile& plan);
Simulation simulate(const Task& task, const State& start, const std::vector<ActionId>& actions);

}  // namespace clips::pddl
