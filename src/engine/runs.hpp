#pragma once
// Whole runs over recorded observations (a dataset plan, or actions and an
// utterance given on the command line) under the same per-call limits as the
// engine's calls: `clips infer`, `clips assist --problem`, Python's run_plan
// and the bench (unbounded) go through here.
#include "clips/types.hpp"
#include "engine/engine.hpp"
#include "inference/belief.hpp"

namespace clips::engine {

// The belief's evidence modality of a method (literal: the CLIPS one).
inference::Modality modality_of(Method m);

// The one conversion of a belief's posterior into the public value type
// (which engine/json.hpp writes): labels from `goals` and `profiles`, the
// hypotheses in `belief`'s order.
Posterior to_posterior(const inference::Posterior& p, const inference::Belief& belief,
                       const std::vector<std::string>& goals, const std::vector<std::string>& profiles);
// One step of a run, under a method.
Posterior posterior_of(const inference::InferenceRun& run, const inference::StepRecord& step, Method m);

// A dataset plan's recorded observations replayed through the engine
// (Engine::replay), with the plan's candidate goals, cost profiles (its tag)
// and true goal: the run `clips infer`, the bench and Python's run_plan
// report. Unbounded.
inference::InferenceRun run_inference(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                                      const inference::InferenceOptions& options = {});
// The same over observations that are not a dataset plan (actions and
// utterances given on the command line): `plan.observed` on the dataset's
// problem `plan.problem_id`; `plan.completed` is not read and no true goal is
// known (true_goal = -1).
inference::InferenceRun run_inference_on_observations(const data::Dataset& ds, const data::PlanRecord& plan,
                                                      lm::LanguageModel& lm,
                                                      const inference::InferenceOptions& options = {});

// Either of the two, bounded by `limits`: every search ends at the deadline,
// and a run that reached it throws TimeLimitError (its numbers would depend
// on where the clock cut it); a cancellation is seen before and after the run.
inference::InferenceRun run_observations(const data::Dataset& ds, const data::PlanRecord& plan, lm::LanguageModel& lm,
                                         inference::InferenceOptions options, bool known_truth,
                                         const CallLimits& limits = {});

// An engine over observations that are not a dataset plan, as
// run_observations replays them, ready for assist().
Engine engine_over_observations(const data::Dataset& ds, const data::PlanRecord& observations,
                                std::shared_ptr<lm::LanguageModel> lm, const inference::InferenceOptions& inference,
                                SessionOptions options, const CallLimits& limits = {});

}  // namespace clips::engine
