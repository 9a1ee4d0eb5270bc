// One grounded Task shared by threads: concurrent goal inferences (each with
// its own goals, hence its own compiled conditions, searches and heuristics)
// give exactly the posteriors they give one after another. Small enough to
// run under TSan.
#include <gtest/gtest.h>

#include <memory>
#include <thread>

#include "domains/builtin/packs.hpp"
#include "inference/belief.hpp"
#include "pddl/parser.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

namespace clips::inference {
namespace {

// A row of seven cells: gem1 at x = 1, gem2 at x = 7, gem3 at x = 4 behind
// nobody; the human and the robot start at x = 3.
const char* kRow = R"(
(define (problem row) (:domain doors-keys-gems)
  (:objects gem1 gem2 gem3 - gem red yellow blue - color robot - robot human - human)
  (:init (= (walls) (new-bit-matrix false 1 7))
         (= (xloc gem1) 1) (= (yloc gem1) 1) (iscolor gem1 red)
         (= (xloc gem2) 7) (= (yloc gem2) 1) (iscolor gem2 yellow)
         (= (xloc gem3) 5) (= (yloc gem3) 1) (iscolor gem3 blue)
         (= (xloc human) 3) (= (yloc human) 1)
         (= (xloc robot) 3) (= (yloc robot) 1)
         (active human) (next-turn human robot) (next-turn robot human)
         (forbidden robot gem1) (forbidden robot gem2) (forbidden robot gem3))
  (:goal (has human gem1)))
)";

struct InferenceRun {
  std::vector<data::GoalSpec> goals;
  std::vector<std::string> actions;
};

// The goal posterior (both modalities) after every step, all steps in a row.
std::vector<double> infer(const std::shared_ptr<const pddl::Task>& task, const InferenceRun& run) {
  InferenceOptions opts;
  opts.heuristic = "hmax";
  Belief b(task, domains::builtin_pack("doors-keys-gems"), run.goals, {fixtures::dkg_profile(1), fixtures::dkg_profile(2)}, opts);
  std::vector<double> out;
  auto keep = [&](const StepRecord& r) {
    const auto& g = r[Modality::Both].goals;
    out.insert(out.end(), g.begin(), g.end());
  };
  keep(b.start(task->initial_state()));
  for (const auto& a : run.actions) keep(b.observe(*task->find_action(a)));
  return out;
}

TEST(SharedTask, ConcurrentInferencesMatchSequentialOnes) {
  auto d = std::make_shared<pddl::Domain>(pddl::load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
  auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, kRow, "row.pddl"));
  auto task = std::make_shared<const pddl::Task>(d, p, domains::builtin_pack("doors-keys-gems")->spec().grounding);
  const std::vector<InferenceRun> runs = {
      {{{"gem1", "(has human gem1)", ""}, {"gem2", "(has human gem2)", ""}},
       {"(left human)", "(wait robot)", "(left human)"}},
      {{{"gem2", "(has human gem2)", ""}, {"gem3", "(has human gem3)", ""}, {"gem1", "(has human gem1)", ""}},
       {"(right human)", "(right robot)", "(right human)", "(wait robot)"}},
      {{{"any", "(or (has human gem1) (has human gem3))", ""}, {"gem2", "(has human gem2)", ""}},
       {"(wait human)", "(left robot)", "(right human)"}},
  };
  std::vector<std::vector<double>> expected;
  for (const auto& r : runs) expected.push_back(infer(task, r));
  for (const auto& e : expected) ASSERT_FALSE(e.empty());
  ASSERT_NE(expected[0], expected[1]);  // the runs really differ

  // Each run twice, all six at once on the one task.
  std::vector<std::vector<double>> got(2 * runs.size());
  std::vector<std::thread> threads;
  for (size_t i = 0; i < got.size(); ++i)
    threads.emplace_back([&, i] { got[i] = infer(task, runs[i % runs.size()]); });
  for (auto& t : threads) t.join();
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected[i % runs.size()]) << "thread " << i;
}

}  // namespace
}  // namespace clips::inference
