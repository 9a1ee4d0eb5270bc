#pragma once
// The particle-inference options shared by `clips infer` and `clips bench`
// (inference::InferenceOptions::particles and friends; belief.hpp).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "inference/belief.hpp"

namespace clips::app {

struct ParticleFlags {
  int particles = 0;  // 0: exact enumeration
  uint64_t seed = 1;
  double ess_threshold = 0.5;
  int moves = 2;
  std::string rejuvenate = "evidence";  // or "utterances", "resampling"
  int groups = 8;
  std::string filters = "all";  // or "clips"
};

// --particles, --particle-seed, --ess-threshold, --rejuvenation-moves, --rejuvenate,
// --proposal-groups, --particle-filters.
void add_particle_options(CLI::App* cmd, ParticleFlags& flags);
// Copies the flags into the inference options.
void apply_particle_flags(const ParticleFlags& flags, inference::InferenceOptions& options);

}  // namespace clips::app
