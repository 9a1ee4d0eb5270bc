#pragma once
// `clips bench particles`: how close particle inference comes to exact
// inference, and at what cost. For every plan of a dataset, exact inference
// runs once and particle inference once per (particle count, seed); the goal
// posteriors of the CLIPS modality (actions + utterances) are compared by
// total variation, TV(p, q) = ½ Σ_g |p_g - q_g|, after the last step and
// averaged over steps, and wall times and hypothesis refinements are
// compared as ratios particle / exact. Both run single-threaded, one plan at
// a time, so the times are comparable.
#include <optional>
#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "clips/types.hpp"
#include "inference/belief.hpp"
#include "inference/particle_belief.hpp"
#include "inference/utterance_model.hpp"
#include "lm/language_model.hpp"

namespace clips::studies {

struct ParticleEvalOptions {
  std::string dataset;
  std::vector<std::string> plans;             // empty: every evaluated plan
  std::vector<int> particles = {64, 128, 256};
  int seeds = 3;                              // particle seeds 1..seeds for each count
  // The filters' tuning (the one particle options type; its particles and
  // particle_seed are not read: the counts and seeds above are).
  ParticleOptions tuning;
  inference::SpeakerRule speaker_rule = inference::SpeakerRule::Paper;
  std::optional<domains::RolloutSettings::Plans> speaker_plans;  // nullopt: the pack's
  inference::UtteranceTiming utterance_timing = inference::UtteranceTiming::After;
  inference::AssistantTurns assistant_turns = inference::AssistantTurns::Taken;
  std::shared_ptr<lm::LanguageModel> language_model;  // required
  bool progress = true;
};

// One particle run against the plan's exact run.
struct ParticleEvalRow {
  std::string plan;
  int goals = 0, hypotheses = 0, steps = 0;
  int particles = 0;
  uint64_t seed = 0;
  double tv_final = 0;        // CLIPS goal posterior after the last step
  double tv_steps_mean = 0;   // mean over steps 0..T
  double tv_steps_max = 0;
  double tv_action_final = 0; // action-only goal posterior after the last step
  double exact_seconds = 0, particle_seconds = 0;
  size_t exact_refinements = 0, particle_refinements = 0;
  int resamples = 0;          // CLIPS modality
};

struct Distribution {
  double mean = 0, min = 0, median = 0, p90 = 0, max = 0;
};
Distribution distribution(std::vector<double> xs);  // empty: all zero

struct ParticleEvalSummary {
  int particles = 0;
  int runs = 0;
  Distribution tv_final, tv_steps;
  double time_ratio = 0;         // Σ particle seconds / Σ exact seconds
  double time_ratio_median = 0;  // median over runs of the per-run ratio
  double refinement_ratio = 0;   // Σ particle refinements / Σ exact refinements
};

struct ParticleEvalReport {
  std::string dataset, lm;
  // The filter settings of every particle run, as option name and value
  // ("ess_threshold", "0.5"), so that a saved report says how it was made.
  std::vector<std::pair<std::string, std::string>> settings;
  int plans = 0;
  std::vector<std::string> failed;  // "plan: error"
  std::vector<ParticleEvalRow> rows;
  std::vector<ParticleEvalSummary> summary;  // one per particle count
};

ParticleEvalReport run_particle_eval(const ParticleEvalOptions& options);
std::string format_particle_eval(const ParticleEvalReport& report);  // human-readable table
nlohmann::json to_json(const ParticleEvalReport& report);

}  // namespace clips::studies
