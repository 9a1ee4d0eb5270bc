#pragma once
// `clips bench --scaling`: how the cost of CLIPS grows with the map side, the
// number of candidate goals (gems) and the length of the observed episode, on
// Doors-Keys-Gems datasets drawn by `clips generate`.
//
// Every point of an axis varies one quantity and keeps the others at their
// defaults (scaling_points()). A point generates its own dataset (seeded,
// deterministic), then for every plan runs CLIPS inference (both modalities)
// and offline Q_MDP assistance through eval::evaluate_plan, timing every
// belief step (StepRecord::seconds) and every assistance decision
// (MethodResult::decision_seconds). The CLI runs each point in its own
// process so that max RSS is per point (getrusage of that process).
//
// Steps axis: the observed prefix of a plan is the first T actions of its
// whole sampled joint sequence (observed + completed), the rest its
// completion; the sequences are sampled on larger maps with a noisier human
// (temperature 2) so that they are long. A plan shorter than T + 1 actions
// gives its whole sequence but the last action (the goal's pick-up). The
// instruction stays at its step when that is inside the prefix, else it is
// heard at the prefix's end.
#include <cstdint>
#include <string>
#include <vector>

#include "lm/language_model.hpp"

namespace clips::studies {

struct ScalingPoint {
  std::string axis;  // "side", "goals" or "steps"
  int value = 0;     // the quantity the axis varies
  int side = 11, gems = 4, keys = 2, doors = 2;
  int steps = 0;              // observed prefix length; 0: as generated
  double temperature = 0.5;   // of the generator's sampled plans
  int max_steps = 0;          // generator's longest plan; 0: the pack's horizon
};

struct ScalingSettings {
  int plans = 4;                        // plans per point (one problem each)
  uint64_t seed = 1;
  size_t max_nodes = size_t{1} << 18;  // per lookahead search (inference and assistance refinements)
  double point_seconds = 300;           // no further plan starts once a point has used this much
  std::string domain_file;              // the mDKG domain (copied into each generated dataset)
};

// Axes of the full run, or of the quick one (smaller values, fewer points).
std::vector<ScalingPoint> scaling_points(bool quick);

struct ScalingRow {
  ScalingPoint point;
  int plans = 0;                 // plans that ran
  int plans_failed = 0;          // plans evaluate_plan could not run (error)
  double observed_steps_mean = 0;
  int belief_steps = 0, decisions = 0;
  double belief_median_ms = 0, belief_p95_ms = 0;
  double decision_median_ms = 0, decision_p95_ms = 0;
  double p_true_mean = 0;        // CLIPS (both modalities), after the last observed step
  size_t budget_stops = 0;       // lookahead searches stopped by max_nodes (inference, all plans)
  double generate_seconds = 0, run_seconds = 0;
  double max_rss_mb = 0;         // of the process that ran the point
  bool time_budget_hit = false;  // point_seconds stopped the point before all plans ran
  std::string error;             // non-empty: the point could not run
};

// Generates the point's dataset (under a temporary folder, removed after)
// and measures it. Errors are reported in ScalingRow::error.
ScalingRow run_scaling_point(const ScalingPoint& point, const ScalingSettings& settings, lm::LanguageModel& lm);

// The CSV: a header line, then one line per row (columns in scaling_csv_header()).
std::string scaling_csv_header();
std::string scaling_csv_line(const ScalingRow& row);
// Parses one line written by scaling_csv_line (the CLI's per-point process
// prints it); throws InputError when it is not one.
ScalingRow parse_scaling_csv_line(const std::string& line);

// Three panels (one per axis, in scaling_points() order), log-scale time
// axes: median and p95 belief step and assistance decision against the
// axis's value. Standalone SVG.
std::string scaling_svg(const std::vector<ScalingRow>& rows);

// Nearest-rank quantile of unsorted values (0 for none).
double scaling_quantile(std::vector<double> xs, double q);

}  // namespace clips::studies
