#pragma once
// `clips bench --scaling` (studies/scaling.hpp): the driver runs every point in
// a child process (`clips bench --scaling-point AXIS:VALUE`, which prints one
// CSV line) so that max RSS is per point, and writes DIR/scaling.csv and
// DIR/scaling.svg after every point.
#include <cstdint>
#include <string>

#include "studies/scaling.hpp"

namespace clips::app {

struct ScalingCli {
  bool run = false;         // --scaling
  bool quick = false;       // --quick
  std::string point;        // --scaling-point AXIS:VALUE (one point, CSV line on stdout)
  std::string out = "docs/scaling";
  studies::ScalingSettings settings;
  std::string lm_kind = "embedded";
};

// Returns the exit status.
int run_scaling_cli(const ScalingCli& cli);

}  // namespace clips::app
