// The public session API on one dataset plan: open a session (not timed),
// then for every observed action observe() it and ask assist(). The same loop
// through the Python binding is timed by bench/python_session_bench.py, which
// reads this benchmark's median to report the binding's overhead.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "clips/clips.hpp"
#include "data/dataset.hpp"

namespace {

// The paper's 2.1.keys when the shared dataset is there, else a repo example
// (the Python script makes the same choice).
std::pair<std::string, std::string> session_plan() {
  std::string root = std::getenv("CLIPS_DATASET") ? std::getenv("CLIPS_DATASET")
                                                  : std::string(CLIPS_SOURCE_DIR) + "/../shared/dataset";
  if (std::filesystem::exists(root + "/doors-keys-gems/domain.pddl")) return {root + "/doors-keys-gems", "2.1.keys"};
  return {std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems", "e2.2.keys"};
}

}  // namespace

static void BM_SessionObserveAssist(benchmark::State& st) {
  const auto [dir, plan_id] = session_plan();
  const auto ds = clips::data::Dataset::load(dir);
  std::vector<std::string> actions;
  for (const auto& line : ds.plan(plan_id).observed.actions) actions.push_back(line.text);
  size_t decisions = 0;
  for (auto _ : st) {
    st.PauseTiming();
    auto session = clips::Session::open_dataset(dir, plan_id);
    st.ResumeTiming();
    for (const auto& a : actions) {
      session.observe(a);
      const auto d = session.assist();
      decisions += d.assistant_turn;
      benchmark::DoNotOptimize(d);
    }
  }
  st.counters["actions"] = static_cast<double>(actions.size());
  st.counters["decisions"] = static_cast<double>(decisions) / static_cast<double>(st.iterations());
}
BENCHMARK(BM_SessionObserveAssist)->Unit(benchmark::kMillisecond)->UseRealTime();
