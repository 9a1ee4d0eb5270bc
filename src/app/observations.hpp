#pragma once
// Ad-hoc observations for `clips infer` and `clips assist`: instead of a
// dataset plan (--plan ID), a dataset problem (--problem P) with actions and
// an utterance given on the command line. They become a PlanRecord on that
// problem, checked in full before any inference runs.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "data/dataset.hpp"

namespace clips::app {

struct ObservationFlags {
  std::string plan;                   // --plan ID (the dataset's own observations)
  std::string problem;                // --problem P
  std::string actions;                // --actions FILE or "(a ...) (b ...)"
  std::optional<std::string> utterance;
  std::optional<int> utterance_step;  // actions before the utterance (default 0)
  std::string condition;              // a pack's plan tag ("": its first); picks the cost profiles
};

void add_observation_options(CLI::App* cmd, ObservationFlags& f);

// Checks the flags that need no data (which of --plan / --problem, a valid
// UTF-8 utterance, ...); throws UsageError or InputError. Call first.
void check_observation_flags(const ObservationFlags& f);

// The observations as a plan record on the dataset's problem: actions
// resolved and simulated from the initial state (an error names the action,
// its position and why it is unknown or inapplicable), the utterance placed
// after `utterance_step` actions.
data::PlanRecord observations_record(const data::Dataset& ds, const ObservationFlags& f);

}  // namespace clips::app
