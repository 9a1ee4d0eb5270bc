#pragma once
// A bench run broken down the ways a held-out evaluation needs: by the
// dataset's dev/test split, by the kind of instruction (instructions.tsv),
// and how well calibrated each inference method's goal posterior is after
// the instruction.
//
// Calibration: every (plan, candidate goal) pair is one forecast, the goal's
// posterior probability p after the instruction, with outcome 1 when it is
// the plan's true goal. Forecasts are binned by p in ten bins of width 0.1;
// the reliability diagram plots each bin's observed frequency against its
// mean p, and the expected calibration error is the bin-size-weighted mean
// of |frequency - mean p|.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "eval/bench.hpp"
#include "eval/metrics.hpp"

namespace clips::eval {

struct SplitRow {
  std::string split;   // "dev", "test"
  std::string method;
  int n = 0;           // plans the method ran on without an error
  std::map<std::string, MeanSe> metrics;  // p_true_goal, assist_precision, assist_recall
};

struct CategoryRow {
  std::string category;
  std::string split;   // "" = both splits
  int n = 0;           // plans with the category
  std::map<std::string, double> p_true_goal;  // per inference method
  std::map<std::string, double> precision;    // per method with assistance
};

struct ReliabilityBin {
  double lo = 0, hi = 0;
  int n = 0;
  double mean_p = 0, frequency = 0;
};

struct Calibration {
  std::string method;
  std::string split;  // "" = both splits
  int forecasts = 0;  // (plan, goal) pairs
  double ece = 0;
  std::vector<ReliabilityBin> bins;  // ten, empty ones included (n = 0)
};

struct Breakdown {
  std::vector<SplitRow> splits;
  std::vector<CategoryRow> categories;
  std::vector<Calibration> calibration;
  bool empty() const { return splits.empty() && categories.empty() && calibration.empty(); }
};

// Splits and categories appear only when some plan has them; calibration for
// every inference method (one with a goal posterior).
Breakdown breakdown(const BenchReport& r);
// Plain-text tables for the terminal, after the main table ("" when empty).
std::string breakdown_table(const Breakdown& b);
nlohmann::ordered_json breakdown_json(const Breakdown& b);
// A reliability diagram of one method (SVG text).
std::string reliability_svg(const Calibration& c);

}  // namespace clips::eval
