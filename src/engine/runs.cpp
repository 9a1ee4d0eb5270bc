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

inference::InferenceRun run_observations(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                                         inference::InferenceOptions options, bool known_truth,
                                         const CallLimits& limits) {
  if (std::isnan(limits.seconds) || limits.seconds < 0)
    throw InputError(fmt::format("the time limit must be a number of seconds >= 0, not {}", limits.seconds));
  auto cancelled = [&] { return limits.cancel && limits.cancel->load(); };
  const auto check_cancel = [&] {
    if (cancelled()) throw CancelledError("the run was cancelled");
  };
  check_cancel();
  Clock::time_point deadline = Clock::time_point::max();
  if (limits.seconds < 1e9)
    deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.seconds));
  options.refine.deadline = std::min(options.refine.deadline, deadline);
  inference::InferenceRun run = known_truth ? inference::run_inference(ds, plan, lm, options)
                                            : inference::run_inference_on_observations(ds, plan, lm, options);
  if (deadline != Clock::time_point::max() && Clock::now() >= deadline)
    throw TimeLimitError(fmt::format("the time limit of {:g} s was reached", limits.seconds));
  check_cancel();
  return run;
}

Engine engine_over_observations(const data::Dataset& ds, const data::PlanRecord& observations,
                                std::shared_ptr<lm::LanguageModel> lm, const inference::InferenceOptions& inference,
                                SessionOptions options, const CallLimits& limits) {
  inference::InferenceRun run = run_observations(ds, observations, *lm, inference, false, limits);
  Problem p;
  p.dataset = std::filesystem::path(ds.dir()).filename().string();
  p.problem = observations.problem_id;
  p.task = ds.task(observations.problem_id);
  p.pack = ds.pack_ptr();
  options.max_nodes = inference.refine.max_nodes;
  options.threads = inference.threads;
  return Engine::adopt(std::move(p), std::move(options), std::move(run), std::move(lm));
}

}  // namespace clips::engine
