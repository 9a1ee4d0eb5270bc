#pragma once
// Read access to a Session's task, state and pack, for in-tree front ends
// that draw the state (the Python module's scene_png). Not installed: the
// public surface stays include/clips/.
#include "clips/session.hpp"
#include "domains/pack.hpp"
#include "pddl/task.hpp"

namespace clips {

struct SessionInternals {
  static const pddl::Task& task(const Session& s);
  static const pddl::State& state(const Session& s);
  static const domains::Pack& pack(const Session& s);
};

}  // namespace clips
