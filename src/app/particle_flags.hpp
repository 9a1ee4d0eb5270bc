#pragma once
// The particle-inference options shared by `clips infer` and `clips bench`
// (inference::InferenceOptions::particles and friends; belief.hpp).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "clips/types.hpp"
#include "engine/runs.hpp"  // the inference options the flags set

namespace clips::app {

using ParticleFlags = inference::ParticleSettings;

// --particles, --particle-seed, --ess-threshold, --rejuvenation-moves, --rejuvenate,
// --proposal-groups, --particle-filters, --particle-estimate.
void add_particle_options(CLI::App* cmd, ParticleFlags& flags);
// Copies the flags into the inference options (inference::apply_particle_settings).
inline void apply_particle_flags(const ParticleFlags& flags, inference::InferenceOptions& options) {
  inference::apply_particle_settings(flags, options);
}
// The same into a session engine's options (checked as above).
void apply_particle_flags(const ParticleFlags& flags, SessionOptions& options);

}  // namespace clips::app
