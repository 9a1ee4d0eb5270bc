// Successor generation and A* throughput on Doors-Keys-Gems states.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <set>

#include "data/dataset.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "heuristics/basic.hpp"
#include "search/astar.hpp"

using namespace clips;

namespace {

std::string dataset_dir() {
  if (const char* e = std::getenv("CLIPS_DATASET")) return std::string(e) + "/doors-keys-gems";
  std::string shared = std::string(CLIPS_SOURCE_DIR) + "/../shared/dataset/doors-keys-gems";
  if (std::filesystem::exists(shared)) return shared;
  return std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
}

// States along every observed plan and completion: realistic mid-task states.
struct Corpus {
  data::Dataset ds = data::Dataset::load(dataset_dir());
  std::vector<std::pair<std::shared_ptr<const pddl::Task>, pddl::State>> states;
  Corpus() {
    for (auto& p : ds.plans()) {
      auto t = ds.task(p.problem_id);
      auto obs = pddl::simulate(*t, t->initial_state(), p.observed);
      auto comp = pddl::simulate(*t, obs.states.back(), p.completed);
      for (auto& s : obs.states) states.push_back({t, s});
      for (auto& s : comp.states) states.push_back({t, s});
    }
  }
};

Corpus& corpus() {
  static Corpus c;
  return c;
}

}  // namespace

static void BM_SuccessorGeneration(benchmark::State& st) {
  auto& c = corpus();
  std::vector<pddl::ActionId> acts;
  std::vector<uint64_t> child(64);
  size_t generated = 0;
  for (auto _ : st) {
    for (auto& [t, s] : c.states) {
      t->applicable_actions(s.data(), acts);
      for (auto a : acts) {
        t->apply(a, s.data(), child.data());
        benchmark::DoNotOptimize(child[0]);
      }
      generated += acts.size();
    }
  }
  st.counters["successors/s"] = benchmark::Counter(static_cast<double>(generated), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SuccessorGeneration)->Unit(benchmark::kMillisecond);

static void BM_AStarBlindExpansions(benchmark::State& st) {
  auto& c = corpus();
  // Uniform-cost search on every problem for the red gem, 20k expansions each.
  std::vector<model::Specification> specs;
  std::set<std::string> seen;
  for (auto& p : c.ds.plans())
    if (seen.insert(p.problem_id).second)
      specs.emplace_back(c.ds.task(p.problem_id), "(has human gem1)", domains::builtin_pack("doors-keys-gems")->cost_profile("C1"));
  heuristics::BlindHeuristic blind;
  search::SearchOptions o;
  o.max_nodes = 20000;
  size_t expanded = 0;
  for (auto _ : st) {
    for (auto& spec : specs) {
      auto r = search::plan(spec, blind, spec.task().initial_state(), o);
      expanded += r.expanded;
    }
  }
  st.counters["expansions/s"] = benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_AStarBlindExpansions)->Unit(benchmark::kMillisecond);
