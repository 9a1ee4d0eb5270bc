// Plan files with `;` utterance comments: parsing, then resolving and
// simulating every action line on the blocks example (data/examples/blocks).
#include <memory>

#include "fuzz/fuzz_target.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "util/data_dir.hpp"

namespace {

const clips::pddl::Task& blocks_task() {
  static const clips::pddl::Task task = [] {
    using namespace clips::pddl;
    const std::string dir = clips::util::data_path("examples/blocks");
    auto domain = std::make_shared<Domain>(load_domain(dir + "/domain.pddl"));
    auto problem = std::make_shared<Problem>(load_problem(*domain, dir + "/p1.pddl"));
    return Task(domain, problem);
  }();
  return task;
}

}  // namespace

#ifdef CLIPS_LIBFUZZER
// Load the task before the first input, so it does not count against -timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  (void)blocks_task();
  return 0;
}
#endif

CLIPS_FUZZ_TARGET(plan) {
  using namespace clips::pddl;
  const Task& task = blocks_task();
  try {
    const PlanFile plan = parse_plan(clips::fuzz::as_text(data, size), "<plan>");
    for (const auto& u : plan.utterances) {
      if (u.index < 0 || u.index > static_cast<int>(plan.actions.size())) __builtin_trap();
    }
    const Simulation sim = simulate(task, task.initial_state(), plan);
    if (sim.states.size() != sim.actions.size() + 1) __builtin_trap();
  } catch (const clips::InputError&) {
  }
  return 0;
}
