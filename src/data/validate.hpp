#pragma once
// Dataset validation: every observed plan and its completion must simulate,
// the completion must reach exactly one candidate goal, and that goal must be
// the plan's true goal (and agree with stimuli.json and the utterance files
// where present).
#include <string>
#include <vector>

#include "data/dataset.hpp"

namespace clips::data {

struct PlanCheck {
  std::string plan_id;
  bool ok = false;
  std::string error;
  int observed_steps = 0, completed_steps = 0;
  std::string goal;  // label of the goal reached
};

struct ValidationReport {
  std::vector<PlanCheck> results;
  int failed = 0;
};

PlanCheck validate_plan(const Dataset& ds, const PlanRecord& p);
// Every plan, then every plan that failed to load (Dataset::broken_plans()).
ValidationReport validate_dataset(const Dataset& ds);

// The assistance options the robot took in a joint plan: distinct keys picked
// up (condition "keys") or doors unlocked (condition "doors") by the robot;
// VH: items grabbed by the helper. Object names in order of first use.
std::vector<std::string> true_options(const Dataset& ds, const PlanRecord& p);

}  // namespace clips::data
