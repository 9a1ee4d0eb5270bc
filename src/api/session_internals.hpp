#pragma once
// Read access to a Session's task, state, pack and event log, for in-tree
// front ends (the Python module draws the state and keeps its replay log in
// step with undo()). Not installed: the public surface stays include/clips/.
#include <string>
#include <utility>
#include <vector>

#include "clips/session.hpp"
#include "domains/pack.hpp"
#include "pddl/task.hpp"

namespace clips {

struct SessionInternals {
  static const pddl::Task& task(const Session& s);
  static const pddl::State& state(const Session& s);
  static const domains::Pack& pack(const Session& s);
  // The actions and utterances the session holds, in order: (is an utterance, text).
  static std::vector<std::pair<bool, std::string>> events(const Session& s);
};

}  // namespace clips
