#pragma once
// An object a pack's code needs by name (e.g. the literal listener's agents).
#include <string>

#include "pddl/task.hpp"
#include "util/error.hpp"

namespace clips::domains {

// InputError naming the object when the problem has none of that name.
inline pddl::ObjectId require_object(const pddl::Task& task, const std::string& name) {
  auto o = task.find_object(name);
  if (!o) throw InputError("the problem has no object '" + name + "' (needed by the literal listener)");
  return *o;
}

}  // namespace clips::domains
