#pragma once
// The one place a posterior becomes the assistant's hypotheses: each
// hypothesis' weight, its policy, and what the latest instruction asked for
// under it (the request rule). The live engine and the bench's assistance
// episodes (eval/methods.cpp) both build them here.
#include <memory>
#include <vector>

#include "assist/assist.hpp"
#include "inference/belief.hpp"

namespace clips::engine {

// How a hypothesis holds its policy: a copy (refining it leaves the belief
// as it was) or the belief's own (an online belief that refines as it goes).
enum class PolicyUse { Copy, Share };

// What the latest utterance of `steps` asked for, per hypothesis; all null
// for a modality that does not listen (action-only).
std::vector<std::shared_ptr<const assist::Request>> requests_for(const pddl::Task& task,
                                                                 const std::vector<inference::StepRecord>& steps,
                                                                 size_t hypotheses, inference::Modality m);

// The posterior's weights as the assistant reads them: an alone twin's
// weight (model::CostProfile::twin_of) moves to the hypothesis of the same
// goal under the twin's base profile, since the twin says how the principal
// chooses, not what help costs; the twin keeps weight 0, so the indexing
// stays the belief's.
std::vector<double> assistant_weights(const inference::Belief& belief, const inference::Posterior& post);

// The posterior's hypotheses with their policies and the requests attached.
std::vector<assist::Hypothesis> assistant_hypotheses(inference::Belief& belief, const inference::Posterior& post,
                                                     const std::vector<std::shared_ptr<const assist::Request>>& requests,
                                                     PolicyUse use);
std::vector<assist::Hypothesis> assistant_hypotheses(const inference::Belief& belief, const inference::Posterior& post,
                                                     const std::vector<std::shared_ptr<const assist::Request>>& requests);

}  // namespace clips::engine
