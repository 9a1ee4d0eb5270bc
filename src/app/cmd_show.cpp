// `clips show`: the state of a plan at a step, as text.
#include <fmt/core.h>

#include <optional>

#include "app/cli.hpp"
#include "data/dataset.hpp"

namespace clips::app {

void register_show(CLI::App& app) {
  auto* cmd = app.add_subcommand("show", "Print the state of a plan at a step (ASCII grid for Doors-Keys-Gems)");
  struct Opts {
    std::string dataset, plan;
    std::optional<int> step;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory");
  cmd->add_option("--plan", o->plan, "Plan id, e.g. 2.1.keys")->required();
  cmd->add_option("--step", o->step,
                  "Number of actions applied, counting the observed plan then its completion "
                  "(default: the end of the observed plan)")
      ->check(NonNegativeInteger);
  cmd->callback([o] {
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    const auto& p = ds.plan(o->plan);
    auto task = ds.task(p.problem_id);
    auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
    auto comp = pddl::simulate(*task, obs.states.back(), p.completed);
    int T = static_cast<int>(obs.actions.size());
    int total = T + static_cast<int>(comp.actions.size());
    int step = o->step.value_or(T);
    if (step > total) throw InputError("--step " + std::to_string(step) + " is past the end of the plan (" + std::to_string(total) + " actions)");
    const pddl::State& s = step <= T ? obs.states[step] : comp.states[step - T];
    fmt::print("plan {} (problem {}), step {}/{} ({} observed)\n", p.id, p.problem_id, step, total, T);
    if (step > 0) {
      std::string last = step <= T ? task->action_name(obs.actions[step - 1]) : task->action_name(comp.actions[step - T - 1]);
      fmt::print("last action: {}\n", last);
    }
    for (auto& u : p.observed.utterances)
      if (u.index <= step) fmt::print("utterance (after {} actions): \"{}\"\n", u.index, u.text);
    fmt::print("{}", ds.pack().describe_state(*task, s));
  });
}

}  // namespace clips::app
