#pragma once
// `clips bench`: every plan of a dataset directory x every method, in
// parallel over plans, with deterministic results for a given seed whatever
// the number of jobs; aggregated like the paper's Table 1.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "eval/experiment.hpp"
#include "eval/metrics.hpp"

namespace clips::eval {

struct BenchOptions {
  std::string dataset;
  int jobs = 0;  // 0: all cores
  ExperimentOptions experiment;
  std::string lm = "embedded";
  std::string lm_base_url, lm_model;
  std::vector<std::string> plans;  // empty: every evaluated plan
  bool progress = true;
};

struct MethodSummary {
  std::string method;
  std::map<std::string, MeanSe> metrics;  // p_true_goal, assist_precision, ...
};

struct BenchReport {
  std::string domain, dataset, lm;
  std::string speaker_rule;      // the CLIPS speaker model's command rule
  std::string utterance_timing;  // before or after the action at the utterance's index
  std::string qa_floor;          // Q_MDP floor: dead-ends or horizon
  std::vector<PlanOutcome> plans;  // in dataset order
  std::vector<MethodSummary> summary;
  double wall_seconds = 0;
  long max_rss_kb = 0;
  int failed_plans = 0;
  // The dataset the plans ran on (loaded once, shared by every worker);
  // write_report reuses it instead of loading it again.
  std::shared_ptr<const data::Dataset> loaded;
};

BenchReport run_bench(const BenchOptions& opts);

// Writers.
std::string summary_json(const BenchReport& r);
std::string results_csv(const BenchReport& r);
// A table laid out like the paper's Table 1, with its numbers beside ours.
std::string results_table(const BenchReport& r, const std::string& paper_json_path);

}  // namespace clips::eval
