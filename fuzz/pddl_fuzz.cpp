// PDDL domain + problem parsing and grounding. The input is the domain text,
// a form feed (\f), then the problem text; without a \f the problem is empty.
// Sizes are bounded here so that grounding cannot blow up by design (its
// work grows as objects^parameters): large inputs and tasks whose estimated
// ground size is large are skipped, not fuzzed.
#include <memory>
#include <optional>

#include "fuzz/fuzz_target.hpp"
#include "pddl/parser.hpp"
#include "pddl/task.hpp"

namespace {

constexpr size_t kMaxInputBytes = 8192;
constexpr double kMaxGroundSize = 20000;  // ground actions + atoms + fluents + goal bindings

// An upper bound on the number of ground actions, atoms and fluents (each
// typed variable may take every object of its type, a quantified one every
// object), plus the bindings of a quantified goal.
double ground_size(const clips::pddl::Domain& d, const clips::pddl::Problem& p) {
  const double n = static_cast<double>(p.objects.size());
  auto of_type = [&](clips::pddl::TypeId t) {
    double k = 0;
    for (const auto& o : p.objects) k += d.is_subtype(o.type, t) ? 1 : 0;
    return k;
  };
  auto product = [&](const std::vector<clips::pddl::TypeId>& types) {
    double r = 1;
    for (auto t : types) r *= of_type(t);
    return r;
  };
  auto power = [](double base, int exp) {
    double r = 1;
    for (int i = 0; i < exp; ++i) r *= base;
    return r;
  };
  double total = power(n, p.goal_num_vars);
  for (const auto& a : d.actions)
    total += product(a.param_types) * power(n, a.num_vars - static_cast<int>(a.param_types.size()));
  for (const auto& pr : d.predicates) total += product(pr.arg_types);
  for (const auto& f : d.functions) total += product(f.arg_types);
  return total;
}

}  // namespace

CLIPS_FUZZ_TARGET(pddl) {
  using namespace clips::pddl;
  if (size > kMaxInputBytes) return 0;
  const std::string text = clips::fuzz::as_text(data, size);
  const size_t cut = text.find('\f');
  const std::string domain_text = text.substr(0, cut);
  const std::string problem_text = cut == std::string::npos ? "" : text.substr(cut + 1);
  try {
    auto domain = std::make_shared<Domain>(parse_domain(domain_text, "<domain>"));
    auto problem = std::make_shared<Problem>(parse_problem(*domain, problem_text, "<problem>"));
    if (ground_size(*domain, *problem) > kMaxGroundSize) return 0;
    const Task task(domain, problem);
    // Walk a few steps (first applicable action each time), checking the goal.
    std::optional<CompiledCondition> goal;
    if (problem->goal) goal = task.compile(*problem->goal, std::vector<ObjectId>(problem->goal_num_vars, -1));
    State s = task.initial_state();
    (void)task.state_str(s);
    for (int step = 0; step < 4; ++step) {
      if (goal) (void)goal->holds(s);
      const auto next = task.applicable_actions(s);
      if (next.empty()) break;
      (void)task.action_name(next.front());
      s = task.apply(s, next.front());
    }
  } catch (const clips::InputError&) {
  }
  return 0;
}
