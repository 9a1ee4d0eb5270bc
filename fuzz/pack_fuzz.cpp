// The domain declaration file (pack.json). The input is the file's text: it
// is parsed, checked against a small two-agent fetch domain, built into a
// pack (its "code" may pick compiled hooks), and asked what the rest of clips
// asks a pack about one grounded problem: goals, profiles, heuristics,
// literal candidates, options, the state text. Its language.goal_atoms
// templates (given, or derived from the salient actions' effects as
// pack_for_domain does) are expanded for every literal candidate into the
// goal formula the listener plans for, and compiled against the task: a pack
// the checks accept must not fail there with anything but an InputError
// (issue 46: "(holding $1 $7)" passed `validate` and failed in `listen`).
// Whatever the file says, the pack either is rejected with an InputError or
// answers without crashing.
#include <memory>

#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "fuzz/fetch_domain.hpp"
#include "fuzz/fuzz_target.hpp"
#include "commands/command.hpp"
#include "pddl/parser.hpp"
#include "pddl/task.hpp"

namespace {

constexpr size_t kMaxInputBytes = 16384;
constexpr size_t kMaxGoalFormulas = 64;

}  // namespace

CLIPS_FUZZ_TARGET(pack) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const pddl::Task& task = fuzz::fetch_task();
  try {
    domains::PackSpec spec = domains::parse_pack_spec(fuzz::as_text(data, size), "<pack.json>");
    domains::check_pack_code(spec, task.domain());
    domains::check_pack_against(spec, task.domain());
    domains::derive_goal_atoms(spec, task.domain());
    const domains::PackPtr pack = domains::make_pack(std::move(spec));
    pack->check_problem(task, "<fetch problem>");
    const pddl::State s = task.initial_state();
    if (pack->spec().goals.source != domains::GoalSource::GoalSets) {
      const auto goals = pack->problem_goals(task, "<fetch problem>");
      if (goals.empty()) __builtin_trap();  // an empty candidate set must be an InputError
    }
    (void)pack->profiles_for("");
    for (const auto& name : pack->heuristic_names()) {
      auto h = pack->make_heuristic(name, task);
      if (!h) __builtin_trap();
    }
    size_t expanded = 0;
    for (const auto& term : pack->literal_candidates(task, s)) {
      if (++expanded > kMaxGoalFormulas) break;
      commands::Command command;
      command.actions = {term};
      // std::invalid_argument here (a template the checks let through) is a finding.
      const std::string formula = command.to_goal_formula(pack->spec().language);
      (void)task.compile_text(formula, "<goal of " + term.name + ">").holds(s);
    }
    (void)pack->qualifier_of(task);
    for (pddl::ActionId a : task.applicable_actions(s)) (void)pack->option_of(task, a, "");
    (void)pack->is_option_object(task, "plank1", "");
    (void)pack->describe_state(task, s);
    (void)pack->object_list(task);
  } catch (const InputError&) {
  }
  return 0;
}
