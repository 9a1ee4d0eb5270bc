// Shared helpers of the PDDL tests.
#pragma once

#include <functional>
#include <string>

#include "util/error.hpp"

namespace clips::pddl::testing {

// The message of the InputError `f` throws, or "" if it throws none.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace clips::pddl::testing
