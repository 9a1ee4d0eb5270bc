// Goal conditions with quantifiers (issue 61): the input is a goal's PDDL
// text, compiled against the fetch problem (fuzz/fetch_domain.hpp) as a
// candidate goal is, and judged by data::why_goal_never_holds, which datasets
// use to refuse goals no state can satisfy. The judgement must be sound: a
// goal it calls impossible holds in none of the states a breadth-first walk
// from the initial state reaches. Inputs with more than three quantifiers are
// skipped here: how far nested quantifiers may expand is the grounder's limit
// (its own target, pddl).
#include <deque>
#include <string>
#include <unordered_set>

#include "data/goal_check.hpp"
#include "fuzz/fetch_domain.hpp"
#include "fuzz/fuzz_target.hpp"

namespace {

constexpr size_t kMaxInputBytes = 2048;
constexpr int kMaxQuantifiers = 3;
constexpr size_t kMaxStates = 3000;

int quantifiers(const std::string& text) {
  int n = 0;
  for (const char* q : {"forall", "exists"})
    for (size_t at = text.find(q); at != std::string::npos; at = text.find(q, at + 1)) ++n;
  return n;
}

}  // namespace

CLIPS_FUZZ_TARGET(quantified_goals) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const std::string text = fuzz::as_text(data, size);
  if (quantifiers(text) > kMaxQuantifiers) return 0;
  const pddl::Task& task = fuzz::fetch_task();
  try {
    const pddl::CompiledCondition goal = task.compile_text(text, "<goal>");
    const pddl::State s0 = task.initial_state();
    const std::string why = data::why_goal_never_holds(task, goal, s0);
    if (why.empty()) return 0;
    // Called impossible: then no reachable state may satisfy it.
    std::deque<pddl::State> open{s0};
    std::unordered_set<pddl::State, pddl::StateHash> seen{s0};
    while (!open.empty() && seen.size() < kMaxStates) {
      const pddl::State s = std::move(open.front());
      open.pop_front();
      if (goal.holds(s)) __builtin_trap();
      for (pddl::ActionId a : task.applicable_actions(s)) {
        pddl::State next = task.apply(s, a);
        if (seen.insert(next).second) open.push_back(std::move(next));
      }
    }
  } catch (const InputError&) {
  }
  return 0;
}
