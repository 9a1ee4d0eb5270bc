#include "data/validate.hpp"

#include <algorithm>
#include <set>

#include "pddl/parser.hpp"

namespace clips::data {

std::vector<std::string> true_options(const Dataset& ds, const PlanRecord& p) {
  std::shared_ptr<const pddl::Task> task;
  try {
    task = ds.task(p.problem_id);
  } catch (const InputError&) {
    // Without the problem, option types are not checked (validate_plan reports the problem).
  }
  return ds.pack().options_taken(p.completed, p.tag, task.get());
}

namespace {
int trailing_number(const std::string& s) {
  size_t i = s.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1]))) --i;
  return i < s.size() ? std::stoi(s.substr(i)) : -1;
}
}  // namespace

PlanCheck validate_plan(const Dataset& ds, const PlanRecord& p) {
  PlanCheck r;
  r.plan_id = p.id;
  try {
    auto task = ds.task(p.problem_id);
    auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
    auto comp = pddl::simulate(*task, obs.states.back(), p.completed);
    r.observed_steps = static_cast<int>(obs.actions.size());
    r.completed_steps = static_cast<int>(comp.actions.size());
    auto goals = ds.candidate_goals(p);
    // Whatever the pack's rule for the true goal, the completion must reach
    // it, and no other goal but its parts.
    int truth = ds.true_goal_index(p);
    int reached = -1;
    try {
      reached = domains::reached_goal_index(*task, goals, p.observed, p.completed);
    } catch (const InputError& e) {
      r.error = e.what();
      return r;
    }
    if (reached != truth) {
      r.error = "completion reaches " + goals[reached].label + " but the dataset's true goal is " + goals[truth].label;
      return r;
    }
    r.goal = goals[truth].label;
    if (ds.pack().spec().max_utterances_per_plan == 1) {
      if (p.observed.utterances.size() != 1) {
        r.error = "expected exactly one utterance in the observed plan, found " + std::to_string(p.observed.utterances.size());
        return r;
      }
      if (p.pragmatic_utterance && *p.pragmatic_utterance != p.observed.utterances[0].text) {
        r.error = "utterances/pragmatic/" + p.id + ".txt differs from the observed plan's utterance";
        return r;
      }
      if (auto st = ds.stimulus(p.id)) {
        if (st->timesteps != r.observed_steps) {
          r.error = "stimuli.json says timesteps " + std::to_string(st->timesteps) + ", plan has " + std::to_string(r.observed_steps);
          return r;
        }
        if (st->goal != truth) {
          r.error = "stimuli.json goal index " + std::to_string(st->goal) + " differs from the completion's goal " + std::to_string(truth);
          return r;
        }
        std::vector<int> nums;
        for (auto& o : true_options(ds, p)) nums.push_back(trailing_number(o));
        std::sort(nums.begin(), nums.end());
        if (nums != st->best_options) {
          r.error = "stimuli.json best_option differs from the robot's actions in the completion";
          return r;
        }
      }
    }
    r.ok = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

ValidationReport validate_dataset(const Dataset& ds) {
  ValidationReport rep;
  for (auto& p : ds.plans()) {
    rep.results.push_back(validate_plan(ds, p));
    if (!rep.results.back().ok) ++rep.failed;
  }
  // Plans whose files did not load are failures too, each with its file's error.
  for (auto& b : ds.broken_plans()) {
    PlanCheck c;
    c.plan_id = b.id;
    c.error = b.error;
    rep.results.push_back(std::move(c));
    ++rep.failed;
  }
  return rep;
}

}  // namespace clips::data
