// Successor generation: the chunked literal filters and the recompiled
// residual conditions must yield exactly the actions applicable() accepts,
// in ascending ActionId order, on reachable and on scrambled states.
#include <gtest/gtest.h>

#include <random>

#include "pddl/parser.hpp"
#include "pddl/task.hpp"
#include "test_paths.hpp"

using namespace clips;
using namespace clips::pddl;

namespace {

std::vector<ActionId> brute_force(const Task& t, const State& s) {
  std::vector<ActionId> out;
  for (ActionId a = 0; a < t.num_actions(); ++a)
    if (t.applicable(a, s.data())) out.push_back(a);
  return out;
}

// Random walks from the initial state, plus copies with random atom bits and
// fluent values, so that combinations no plan reaches are covered too.
void check_task(const Task& t, unsigned seed) {
  std::mt19937 rng(seed);
  State s = t.initial_state();
  std::vector<ActionId> acts;
  for (int step = 0; step < 400; ++step) {
    t.applicable_actions(s.data(), acts);
    ASSERT_EQ(acts, brute_force(t, s)) << t.state_str(s);
    State x = s;
    for (int k = 0; k < 4 && t.num_atoms() > 0; ++k) set_bit(x.data(), static_cast<int>(rng() % t.num_atoms()), rng() & 1);
    for (int k = 0; k < 2 && t.num_fluents() > 0; ++k)
      set_num(x.data(), t.fluent_base(), static_cast<int>(rng() % t.num_fluents()), static_cast<int16_t>(int(rng() % 14) - 2));
    t.applicable_actions(x.data(), acts);
    ASSERT_EQ(acts, brute_force(t, x)) << t.state_str(x);
    if (acts.empty()) s = t.initial_state();
    else s = t.apply(s, acts[rng() % acts.size()]);
    if (brute_force(t, s).empty()) s = t.initial_state();
  }
}

}  // namespace

TEST(Successors, MatchApplicableOnDoorsKeysGems) {
  auto d = std::make_shared<Domain>(load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
  auto p = std::make_shared<Problem>(load_problem(*d, paths::examples_dir() + "/doors-keys-gems/problems/e1.pddl"));
  // With and without `frozen` kept as a state bit (assistance keeps it).
  Task plain(d, p);
  check_task(plain, 1);
  Task frozen(d, p, GroundingOptions{{"frozen"}, {}, false, false});
  check_task(frozen, 2);
}

TEST(Successors, MatchApplicableOnBlocks) {
  auto d = std::make_shared<Domain>(load_domain(paths::examples_dir() + "/blocks/domain.pddl"));
  auto p = std::make_shared<Problem>(load_problem(*d, paths::examples_dir() + "/blocks/p1.pddl"));
  Task t(d, p);
  check_task(t, 3);
}
