#pragma once
// The assistance set-up every front end starts from (bench, the session
// engine): the pack's roles, no-op cost and assistance rule, the belief's
// state, step and search graph, and the caller's rule and budgets. A dataset
// plan's episode adds its completed plan and the options it counts.
#include <chrono>
#include <map>
#include <memory>
#include <optional>

#include "assist/assist.hpp"
#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "inference/belief.hpp"

namespace clips::assist {

struct SetupOptions {
  std::optional<AssistRule> rule;  // the pack's assistance_rule when unset
  QaFloor qa_floor = QaFloor::DeadEnds;
  // Budgets of each search a decision refines with (unset: AssistSetup's
  // defaults), and the wall-clock deadline of the whole call.
  std::optional<size_t> max_nodes;
  std::optional<double> max_seconds;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // At most this many model timesteps after the observed part (a rehearsal
  // of an episode: `clips validate`); unset: the pack's horizon.
  std::optional<int> max_steps;
  // The registered options' values, for registered policies (AssistSetup::registered_options).
  std::map<std::string, std::string> registered_options;
};

AssistSetup setup_for(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                      const inference::Belief& belief, const SetupOptions& options = {});

// The episode of a dataset plan from the belief's state after its observed
// part: its completed plan as the simulated principal's guide, the options
// its tag counts (`pack` must outlive the set-up) and the pack's rule on
// following that plan by index.
AssistSetup setup_for_plan(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                           const inference::Belief& belief, const data::PlanRecord& plan,
                           const SetupOptions& options = {});

}  // namespace clips::assist
