#pragma once
// `clips bench`: every plan of a dataset directory x every method, in
// parallel over plans, with deterministic results for a given seed whatever
// the number of jobs; aggregated like the paper's Table 1.
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "eval/experiment.hpp"
#include "eval/metrics.hpp"
#include "language/listener.hpp"
#include "util/version.hpp"

namespace clips::eval {

// Which of a sweep's N disjoint parts a report holds (`clips bench --shard
// K/N`, `clips bench merge`). The sweep's plans (its selection: the evaluated
// plans, or --plans, in dataset order, then the plans that did not load) are
// dealt round-robin: the plan at position i goes to shard (i mod N) + 1.
// Dealing rather than cutting into blocks mixes easy and hard problems into
// every shard (problems come in dataset order), and shard sizes differ by at
// most one plan.
struct ShardSet {
  int count = 1;                // N; 1: an unsharded run
  std::vector<int> present{1};  // the shards K the report holds, ascending
  static int of_position(size_t position, int count) { return static_cast<int>(position % count) + 1; }
  bool holds_position(size_t position) const;
  std::vector<int> missing() const;  // the K in 1..N not present, ascending
  bool partial() const { return !missing().empty(); }
};

struct BenchOptions {
  std::string dataset;
  int jobs = 0;  // 0: all cores
  ExperimentOptions experiment;
  // The language model: `language_model` when set (the CLI builds it from the
  // same --lm flags as every other subcommand), else lm + lm_options.
  std::shared_ptr<lm::LanguageModel> language_model;
  std::string lm = "embedded";
  language::LanguageModelOptions lm_options;
  std::vector<std::string> plans;  // empty: every evaluated plan
  bool progress = true;
  int shard = 1, shard_count = 1;  // run only shard K = `shard` of N = `shard_count` (see ShardSet)
};

struct MethodSummary {
  std::string method;
  std::map<std::string, MeanSe> metrics;  // p_true_goal, assist_precision, ...
};

struct BenchReport {
  std::string domain, dataset, lm;
  std::string fingerprint;       // dataset_fingerprint(dataset): tells the paper's datasets from others
  std::string started_utc;       // ISO 8601, e.g. 2026-12-02T05:01:02Z
  uint64_t seed = 1;
  std::string assistance;        // a name of assistance_set_choices (eval/methods.hpp)
  std::vector<std::string> methods_requested;  // --methods; empty: the domain's defaults
  std::string speaker_rule;      // the CLIPS speaker model's command rule
  std::string utterance_timing;  // before or after the action at the utterance's index
  std::string qa_floor;          // Q_MDP floor: dead-ends or horizon
  std::string assistant_turns;   // refinement at the assistant's turns: taken or all
  // The chat model of the multimodal baseline when it runs (requested, or in
  // the default methods because an endpoint is configured); "" when it does not.
  std::string chat_model;
  // The build that produced the numbers (a merge keeps its parts').
  std::string clips_version = util::version();
  std::string git_commit = util::git_commit();
  ShardSet shards;
  // Every plan id of the sweep, in the order shards deal them (ShardSet);
  // `plans` holds those of shards.present.
  std::vector<std::string> selection;
  std::vector<PlanOutcome> plans;  // in dataset order
  std::vector<MethodSummary> summary;
  double wall_seconds = 0;
  long max_rss_kb = 0;
  int failed_plans = 0;
  int failed_methods = 0;  // (plan, method) runs that failed on a plan that did not
  // The dataset the plans ran on (loaded once, shared by every worker);
  // write_report reuses it instead of loading it again.
  std::shared_ptr<const data::Dataset> loaded;
};

BenchReport run_bench(const BenchOptions& opts);

// Latency over a report's plans (issue 43), in seconds: n values, their
// median, 95th percentile (the value at rank floor(0.95 (n - 1)) of the
// sorted values, as the Google benchmarks read it) and maximum.
struct LatencyStats {
  size_t n = 0;
  double median = 0, p95 = 0, max = 0;
  static LatencyStats of(std::vector<double> xs);
};
struct BenchLatency {
  // Belief-update steps after an observed action (t >= 1) as the plans ran
  // them (on `inference_threads` threads each), and their work summed over
  // those threads (the time on one thread); the first step of each plan
  // (refinement at s_0 and any instruction heard there) separately.
  int inference_threads = 1;  // the largest any plan used
  LatencyStats step, step_one_thread, start;
  // Assistance decisions (Q_MDP) of `decision_method`: "clips" when it ran,
  // else every method's.
  std::string decision_method;
  LatencyStats decision;
  // Where the time went: the plans' inference (their belief steps) and each
  // method's runs, summed over plans (in the order methods first ran), and
  // the longest single run.
  double inference_seconds = 0;
  std::vector<std::pair<std::string, double>> method_seconds;
  std::string slowest_plan, slowest_method;
  double slowest_seconds = 0;
};
BenchLatency bench_latency(const BenchReport& r);
// Recomputes failed_plans and the per-method summary (means and standard
// errors) from r.plans; run_bench and merging shards both end with it.
void summarise(BenchReport& r);
// "" for a report that covers its whole selection; else one line saying which
// shards it holds and which are missing, for the table and the HTML report.
std::string partial_note(const BenchReport& r);

// Writers.
std::string summary_json(const BenchReport& r);
std::string results_csv(const BenchReport& r);
// Long format, one row per (plan, method, step t, goal): the goal posterior
// after t observed actions, at full precision (%.17g). Inference methods have
// rows for t = 0..T; a method with only a final posterior (multimodal) one
// row per goal at t = T.
std::string posteriors_csv(const BenchReport& r);
// A table laid out like the paper's Table 1, with its numbers beside ours
// when the dataset is one of the paper's (paper_results_for).
std::string results_table(const BenchReport& r, const std::string& paper_json_path);

// A dataset's fingerprint: FNV-1a (64 bits, hex) over the names and bytes of
// domain.pddl and problems/*.pddl, in name order. The paper's datasets have
// theirs recorded in data/paper/results.json ("_fingerprints"), so a folder
// of the same layout and name but other problems is not taken for them.
std::string dataset_fingerprint(const std::string& dir);
// Whether the paper's results (data/paper/results.json) have a row for this
// method in this domain.
bool paper_has_method(const nlohmann::json& paper_all, const std::string& domain, const std::string& method);
// The paper's numbers for the report's domain (results.json's entry), or
// nullptr when the report's dataset is not the paper's.
const nlohmann::json* paper_results_for(const BenchReport& r, const nlohmann::json& paper_all);

}  // namespace clips::eval
