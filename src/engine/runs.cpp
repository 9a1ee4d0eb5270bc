#include "engine/runs.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

namespace clips::engine {

using Clock = std::chrono::steady_clock;

inference::Modality modality_of(Method m) {
  switch (m) {
    case Method::LanguageOnly: return inference::Modality::UtteranceOnly;
    case Method::ActionOnly: return inference::Modality::ActionOnly;
    case Method::Clips:
    case Method::Literal: break;
  }
  return inference::Modality::Both;
}

Posterior to_posterior(const inference::Posterior& p, const inference::Belief& belief,
                       const std::vector<std::string>& goals, const std::vector<std::string>& profiles) {
  Posterior out;
  out.goals = goals;
  out.goal_probabilities = p.goals;
  out.cost_profiles = profiles;
  out.cost_profile_probabilities = p.profiles;
  for (size_t h = 0; h < p.hypotheses.size(); ++h) {
    const auto& hy = belief.hypotheses()[h];
    out.hypotheses.push_back({goals.at(hy.goal), profiles.at(hy.profile), p.hypotheses[h]});
  }
  out.log_marginal_likelihood = p.log_marginal;
  return out;
}

Posterior posterior_of(const inference::InferenceRun& run, const inference::StepRecord& step, Method m) {
  return to_posterior(step[modality_of(m)], *run.belief, run.goals, run.profiles);
}

namespace {

// The engine over a plan's observations, and what the batch callers read of it.
struct Replayed {
  Engine engine;
  inference::InferenceRun run;
};

Replayed replay_plan(const data::Dataset& ds, const data::PlanRecord& plan, std::shared_ptr<lm::LanguageModel> lm,
                     const inference::InferenceOptions& options, bool known_truth, SessionOptions session = {}) {
  const auto t0 = Clock::now();
  Problem p;
  p.dataset = std::filesystem::path(ds.dir()).filename().string();
  p.problem = plan.problem_id;
  p.task = ds.task(plan.problem_id);
  p.pack = ds.pack_ptr();
  p.goals = ds.candidate_goals(plan);
  p.true_goal = known_truth ? ds.true_goal_index(plan) : -1;
  inference::ProfileSet ps = inference::plan_cost_profiles(ds.pack(), plan);
  p.profiles = ps.profiles;
  inference::InferenceRun run;
  run.plan_id = plan.id;
  for (const auto& g : p.goals) run.goals.push_back(g.label);
  run.true_goal = p.true_goal;
  for (const auto& c : p.profiles) run.profiles.push_back(c.name);
  run.true_profile = ps.true_index;
  // The problem's goals and profiles are the plan's, not the options'.
  session.goals.clear();
  session.cost_profiles.clear();
  session.max_nodes = options.refine.max_nodes;
  session.threads = options.threads;
  Engine e = Engine::replay(std::move(p), std::move(session), options, std::move(lm), plan.observed);
  run.steps = e.records();
  run.belief = std::const_pointer_cast<inference::Belief>(e.belief());
  run.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  run.searches_stopped_by_budget = run.belief->searches_stopped_by_budget();
  for (const auto& st : run.steps)
    for (const auto& u : st.utterances)
      if (!u.warning.empty()) run.utterance_warnings.push_back(u.warning);
  return {std::move(e), std::move(run)};
}

// The caller's model, not owned: it outlives the run.
std::shared_ptr<lm::LanguageModel> borrowed(lm::LanguageModel& lm) { return {std::shared_ptr<void>(), &lm}; }

// `work` under `limits`, as run_observations says.
template <typename F>
auto bounded_run(const CallLimits& limits, inference::InferenceOptions& options, F&& work) {
  if (std::isnan(limits.seconds) || limits.seconds < 0)
    throw InputError(fmt::format("the time limit must be a number of seconds >= 0, not {}", limits.seconds));
  const auto check_cancel = [&] {
    if (limits.cancel && limits.cancel->load()) throw CancelledError("the run was cancelled");
  };
  check_cancel();
  Clock::time_point deadline = Clock::time_point::max();
  if (limits.seconds < 1e9)
    deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.seconds));
  options.refine.deadline = std::min(options.refine.deadline, deadline);
  auto out = work();
  if (deadline != Clock::time_point::max() && Clock::now() >= deadline)
    throw TimeLimitError(fmt::format("the time limit of {:g} s was reached", limits.seconds));
  check_cancel();
  return out;
}

}  // namespace

inference::InferenceRun run_inference(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                                      const inference::InferenceOptions& options) {
  return replay_plan(ds, plan, borrowed(lm), options, /*known_truth=*/true).run;
}

inference::InferenceRun run_inference_on_observations(const data::Dataset& ds, const data::PlanRecord& plan,
                                                      lm::LanguageModel& lm,
                                                      const inference::InferenceOptions& options) {
  return replay_plan(ds, plan, borrowed(lm), options, /*known_truth=*/false).run;
}

inference::InferenceRun run_observations(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                                         inference::InferenceOptions options, bool known_truth,
                                         const CallLimits& limits) {
  return bounded_run(limits, options,
                     [&] { return replay_plan(ds, plan, borrowed(lm), options, known_truth).run; });
}

Engine engine_over_observations(const data::Dataset& ds, const data::PlanRecord& observations,
                                std::shared_ptr<lm::LanguageModel> lm, const inference::InferenceOptions& inference,
                                SessionOptions options, const CallLimits& limits) {
  inference::InferenceOptions io = inference;
  return bounded_run(limits, io, [&] {
    return std::move(replay_plan(ds, observations, std::move(lm), io, /*known_truth=*/false, std::move(options)).engine);
  });
}

}  // namespace clips::engine
