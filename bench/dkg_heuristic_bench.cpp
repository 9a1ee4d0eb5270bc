// Cost of one Doors-Keys-Gems heuristic evaluation (A* calls it for every
// generated node). States: every state along each dataset plan (observed
// prefix, then the completion), scored for the plan's true goal under its
// true profile (C1 doors, C3 keys), i.e. the states inference actually sees.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "domains/dkg/dkg_heuristic.hpp"
#include "pddl/plan.hpp"

using namespace clips;

namespace {

std::string dkg_dir() {
  if (const char* e = std::getenv("CLIPS_DATASET")) return std::string(e) + "/doors-keys-gems";
  return std::string(CLIPS_SOURCE_DIR) + "/../shared/dataset/doors-keys-gems";
}

struct PlanStates {
  std::shared_ptr<const pddl::Task> task;
  std::shared_ptr<model::Specification> spec;
  std::vector<pddl::State> states;
};

struct Corpus {
  std::vector<PlanStates> plans;
  size_t total = 0;
  Corpus() {
    if (!std::filesystem::exists(dkg_dir() + "/domain.pddl")) return;
    auto ds = data::Dataset::load(dkg_dir());
    for (const auto& p : ds.plans()) {
      if (p.completed.actions.empty()) continue;
      PlanStates ps;
      ps.task = ds.task(p.problem_id);
      auto obs = pddl::simulate(*ps.task, ps.task->initial_state(), p.observed);
      auto comp = pddl::simulate(*ps.task, obs.states.back(), p.completed);
      // The completion ends with (pickup human gemN): the true goal.
      const auto& last = ps.task->action(comp.actions.back());
      std::string goal = "(has human " + ps.task->object_name(last.args[1]) + ")";
      ps.spec = std::make_shared<model::Specification>(ps.task, goal, domains::builtin_pack("doors-keys-gems")->cost_profile(p.tag == "doors" ? "C1" : "C3"));
      ps.states = obs.states;
      ps.states.insert(ps.states.end(), comp.states.begin() + 1, comp.states.end());
      total += ps.states.size();
      plans.push_back(std::move(ps));
    }
  }
};

Corpus& corpus() {
  static Corpus c;
  return c;
}

template <class H>
void run(benchmark::State& st) {
  auto& c = corpus();
  if (c.plans.empty()) {
    st.SkipWithError("Doors-Keys-Gems dataset not found (set CLIPS_DATASET)");
    return;
  }
  std::vector<std::unique_ptr<H>> hs;
  for (auto& p : c.plans) {
    hs.push_back(std::make_unique<H>());
    hs.back()->prepare(*p.spec, p.task->initial_state());
  }
  double sink = 0;
  for (auto _ : st)
    for (size_t i = 0; i < c.plans.size(); ++i)
      for (const auto& s : c.plans[i].states) sink += hs[i]->estimate(s.data());
  benchmark::DoNotOptimize(sink);
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * c.total));
  // Seconds per estimate (Google Benchmark prints it scaled, e.g. "250n").
  st.counters["per_estimate"] = benchmark::Counter(static_cast<double>(st.iterations() * c.total),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Per-state cost of building the location graph and its MSTs, with warm
// RECURSIVE memo (the steady state inside a search).
void BM_DkgMstEstimate(benchmark::State& st) { run<domains::dkg::DkgMstHeuristic>(st); }
BENCHMARK(BM_DkgMstEstimate)->Unit(benchmark::kMicrosecond);

// The same states with a fresh heuristic per pass: every room/lock pattern
// misses the memo once, so RECURSIVE (path enumeration) is paid too.
void BM_DkgMstEstimateColdMemo(benchmark::State& st) {
  auto& c = corpus();
  if (c.plans.empty()) {
    st.SkipWithError("Doors-Keys-Gems dataset not found (set CLIPS_DATASET)");
    return;
  }
  std::vector<std::shared_ptr<const domains::dkg::DkgMapAnalysis>> maps;
  for (auto& p : c.plans) maps.push_back(domains::dkg::DkgMapAnalysis::build(p.task, p.task->initial_state()));
  double sink = 0;
  for (auto _ : st)
    for (size_t i = 0; i < c.plans.size(); ++i) {
      domains::dkg::DkgMstHeuristic h(maps[i]);
      h.prepare(*c.plans[i].spec, c.plans[i].task->initial_state());
      for (const auto& s : c.plans[i].states) sink += h.estimate(s.data());
    }
  benchmark::DoNotOptimize(sink);
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * c.total));
}
BENCHMARK(BM_DkgMstEstimateColdMemo)->Unit(benchmark::kMicrosecond);

void BM_DkgDistanceEstimate(benchmark::State& st) { run<domains::dkg::DkgDistanceHeuristic>(st); }
BENCHMARK(BM_DkgDistanceEstimate)->Unit(benchmark::kMicrosecond);

// Goal-independent precomputation (rooms, room graph, all-pairs distances)
// for the largest map: paid once per problem.
void BM_DkgMapAnalysisBuild(benchmark::State& st) {
  auto& c = corpus();
  if (c.plans.empty()) {
    st.SkipWithError("Doors-Keys-Gems dataset not found (set CLIPS_DATASET)");
    return;
  }
  const PlanStates* big = &c.plans[0];
  for (auto& p : c.plans)
    if (p.task->num_actions() > big->task->num_actions()) big = &p;
  for (auto _ : st) benchmark::DoNotOptimize(domains::dkg::DkgMapAnalysis::build(big->task, big->task->initial_state()));
}
BENCHMARK(BM_DkgMapAnalysisBuild)->Unit(benchmark::kMicrosecond);

}  // namespace
