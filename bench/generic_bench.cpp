// Agent latency on domains without hand-made heuristics (the generic path:
// h_FF policies, RTAA* refinement over the shared state graph): one belief
// update step and one assistance decision (offline Q_MDP), on one thread,
// for the repo's own datasets (data/datasets/*; the belief step on all four)
// and the larger profiling domain bench/data/storeroom (containers to open,
// locks with keys). Reports
// median, 95th percentile and maximum, like BM_BeliefUpdateStep for mDKG;
// `start_max_ms` is the first step of a plan (refinement at s_0 only).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "engine/runs.hpp"
#include "eval/bench.hpp"
#include "eval/experiment.hpp"
#include "heuristics/heuristic.hpp"
#include "pddl/plan.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"

using namespace clips;

namespace {

std::string source_path(const std::string& rel) { return std::string(CLIPS_SOURCE_DIR) + "/" + rel; }

}  // namespace

static void BM_GenericBeliefUpdateStep(benchmark::State& st, const std::string& rel) {
  auto ds = data::Dataset::load(source_path(rel));
  auto lm = language::make_dataset_language_model("embedded", {}, ds);
  std::vector<double> steps, starts;
  // The embedded LM loads (or trains) on first use: not a belief update.
  std::vector<std::string> problems;
  for (const auto& p : ds.plans())
    if (p.evaluated) problems.push_back(p.problem_id);
  language::warm_up_language_model(*lm, ds, problems);
  for (auto _ : st) {
    steps.clear();
    starts.clear();
    for (auto& p : ds.plans()) {
      if (!p.evaluated) continue;
      inference::InferenceOptions io;
      io.threads = 1;
      auto run = engine::run_inference(ds, p, *lm, io);
      if (!run.steps.empty()) starts.push_back(run.steps[0].seconds);
      for (size_t t = 1; t < run.steps.size(); ++t) steps.push_back(run.steps[t].seconds);
    }
  }
  const auto step = eval::LatencyStats::of(steps), start = eval::LatencyStats::of(starts);
  st.counters["median_ms"] = step.median * 1e3;
  st.counters["p95_ms"] = step.p95 * 1e3;
  st.counters["max_ms"] = step.max * 1e3;
  st.counters["steps"] = static_cast<double>(steps.size());
  st.counters["start_median_ms"] = start.median * 1e3;
  st.counters["start_max_ms"] = start.max * 1e3;
}
BENCHMARK_CAPTURE(BM_GenericBeliefUpdateStep, workshop, std::string("data/datasets/workshop"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_GenericBeliefUpdateStep, storeroom, std::string("bench/data/storeroom"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_GenericBeliefUpdateStep, kitchen, std::string("data/datasets/kitchen"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_GenericBeliefUpdateStep, garden, std::string("data/datasets/garden"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_GenericBeliefUpdateStep, lab, std::string("data/datasets/lab"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

static void BM_GenericAssistanceDecision(benchmark::State& st, const std::string& rel) {
  auto ds = data::Dataset::load(source_path(rel));
  auto lm = language::make_dataset_language_model("embedded", {}, ds);
  std::vector<double> decisions;
  for (auto _ : st) {
    decisions.clear();
    for (auto& p : ds.plans()) {
      if (!p.evaluated) continue;
      eval::ExperimentOptions o;
      o.methods = {"clips"};
      o.inference_threads = 1;
      auto out = eval::evaluate_plan(ds, p, *lm, o);
      if (const auto* r = out.find("clips"))
        decisions.insert(decisions.end(), r->decision_seconds.begin(), r->decision_seconds.end());
    }
  }
  const auto l = eval::LatencyStats::of(decisions);
  st.counters["median_ms"] = l.median * 1e3;
  st.counters["p95_ms"] = l.p95 * 1e3;
  st.counters["max_ms"] = l.max * 1e3;
  st.counters["decisions"] = static_cast<double>(decisions.size());
}
BENCHMARK_CAPTURE(BM_GenericAssistanceDecision, workshop, std::string("data/datasets/workshop"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_GenericAssistanceDecision, storeroom, std::string("bench/data/storeroom"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// One heuristic estimate on the storeroom's states (those along every
// observed plan and completion, for every candidate goal of its problem):
// the per-state cost behind the lookahead searches (hff, hff-plain) and the
// listener's optimal planning (lmcut, hmax).
static void BM_GenericEstimate(benchmark::State& st, const std::string& heuristic) {
  auto ds = data::Dataset::load(source_path("bench/data/storeroom"));
  struct Item {
    std::shared_ptr<model::Specification> spec;
    std::shared_ptr<heuristics::Heuristic> h;
    std::vector<pddl::State> states;
  };
  std::vector<Item> items;
  for (auto& p : ds.plans()) {
    auto task = ds.task(p.problem_id);
    auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
    auto comp = pddl::simulate(*task, obs.states.back(), p.completed);
    std::vector<pddl::State> states = obs.states;
    states.insert(states.end(), comp.states.begin(), comp.states.end());
    for (const auto& g : ds.candidate_goals(p)) {
      Item it;
      it.spec = std::make_shared<model::Specification>(task, g.condition, model::unit_profile());
      it.h = ds.pack().make_heuristic(heuristic, *task);
      it.h->prepare(*it.spec, task->initial_state());
      it.states = states;
      items.push_back(std::move(it));
    }
  }
  double sum = 0;
  size_t n = 0;
  for (auto _ : st)
    for (auto& it : items)
      for (const auto& s : it.states) {
        sum += it.h->estimate(s.data());
        ++n;
      }
  benchmark::DoNotOptimize(sum);
  st.SetItemsProcessed(static_cast<int64_t>(n));  // estimates per second
}
BENCHMARK_CAPTURE(BM_GenericEstimate, hff, std::string("hff"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GenericEstimate, hff_plain, std::string("hff-plain"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GenericEstimate, lmcut, std::string("lmcut"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GenericEstimate, hmax, std::string("hmax"))->Unit(benchmark::kMillisecond);
