#pragma once
// The particle-inference flags of `clips infer`, `clips bench` (and `bench
// particles`) and `clips serve`: one flag per row of the engine's option
// table (engine/options.hpp), registered options included, filling
// clips::ParticleOptions.
#include <CLI/CLI.hpp>

#include <set>
#include <string>

#include "clips/types.hpp"

namespace clips::inference {
struct InferenceOptions;
}

namespace clips::app {

using ParticleFlags = ParticleOptions;

// --particles, --particle-seed, --ess-threshold, --rejuvenation-moves, --rejuvenate,
// --proposal-groups, --particle-filters, --particle-estimate (but those named in
// `skip`), and a flag per option registered at run time (clips::register_option).
void add_particle_options(CLI::App* cmd, ParticleFlags& flags, const std::set<std::string>& skip = {});
// Copies the flags into the inference options (engine::apply_particle_options).
void apply_particle_flags(const ParticleFlags& flags, inference::InferenceOptions& options);
// The same into a session engine's options (checked as above).
void apply_particle_flags(const ParticleFlags& flags, SessionOptions& options);

}  // namespace clips::app
