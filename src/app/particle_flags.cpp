#include "app/particle_flags.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

#include "app/cli.hpp"

namespace clips::app {

namespace {

// More particles than this is a typo, not a setting: each particle costs a
// weight per step and the hypothesis spaces are far smaller.
constexpr long kMaxParticles = 1'000'000;

const CLI::Validator ParticleCount(
    [](std::string& in) -> std::string {
      char* end = nullptr;
      const long v = in.empty() || in.find_first_not_of("0123456789") != std::string::npos
                         ? -1
                         : std::strtol(in.c_str(), &end, 10);
      if (v >= 0 && v <= kMaxParticles && end == in.c_str() + in.size()) return {};
      return in + " is not a particle count (0 for exact inference, or 1 to " + std::to_string(kMaxParticles) + ")";
    },
    "N>=0");

const CLI::Validator UnitInterval(
    [](std::string& in) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(in.c_str(), &end);
      if (!in.empty() && end == in.c_str() + in.size() && v >= 0 && v <= 1) return {};  // false for NaN
      return in + " is not a number between 0 and 1";
    },
    "0..1");

}  // namespace

void add_particle_options(CLI::App* cmd, ParticleFlags& f) {
  cmd->add_option("--particles", f.particles,
                  "Particle inference with N particles per modality (sequential Monte Carlo over goal x cost "
                  "profile; only the hypotheses particles hold are refined). 0: exact enumeration (default)")
      ->check(ParticleCount);
  cmd->add_option("--particle-seed", f.seed, "Seed of the particle filters, 0..2^64-1 (default 1); results are a "
                                             "function of it")
      ->check(SeedValue);
  cmd->add_option("--ess-threshold", f.ess_threshold,
                  "Resample when the effective sample size falls below this share of the particles (0..1, "
                  "default 0.5; 1: every step)")
      ->check(UnitInterval);
  cmd->add_option("--rejuvenation-moves", f.moves,
                  "Metropolis-Hastings sweeps over goals after each resampling (default 2; 0: none; at most 100)")
      ->check(NonNegativeInteger)
      ->check(CLI::Range(0, 100));
  cmd->add_option("--rejuvenate", f.rejuvenate,
                  "When the sweeps run besides after resampling: evidence (after every human action or utterance; "
                  "default), utterances (after steps with an utterance: cheaper, and enough for instructions that "
                  "point away from the goals the actions favoured) or resampling (never else: cheapest, but the "
                  "particles can stay on goals that new evidence turns against)")
      ->check(CLI::IsMember({"evidence", "utterances", "resampling"}));
  cmd->add_option("--proposal-groups", f.groups,
                  "Independent exploring proposals per sweep: each sweep may bring in this many new hypotheses per "
                  "hypothesis held (default 8, at most 64; fewer: cheaper, slower to find goals no particle holds)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 64));
  cmd->add_option("--particle-filters", f.filters,
                  "Which posteriors get particles of their own: all (one filter per modality, default) or clips "
                  "(only the CLIPS posterior; the action-only and language-only ones are reweighted from its "
                  "particles: much cheaper, but rough where they disagree with CLIPS)")
      ->check(CLI::IsMember({"all", "clips"}));
  cmd->add_option("--particle-estimate", f.estimate,
                  "How particles give the posterior: support (the exact posterior over the hypotheses the particles "
                  "hold, default: no counting noise) or weights (the weighted particle counts)")
      ->check(CLI::IsMember({"support", "weights"}));
}

void apply_particle_flags(const ParticleFlags& flags, SessionOptions& options) {
  inference::InferenceOptions checked;
  inference::apply_particle_settings(flags, checked);  // an InputError names a bad value
  options.particles = flags.particles;
  options.particle_seed = flags.seed;
  options.ess_threshold = flags.ess_threshold;
  options.rejuvenation_moves = flags.moves;
  options.rejuvenate = flags.rejuvenate;
  options.proposal_groups = flags.groups;
  options.particle_filters = flags.filters;
  options.particle_estimate = flags.estimate;
}

}  // namespace clips::app
