#include "engine/hypotheses.hpp"

#include <stdexcept>

#include "assist/request.hpp"

namespace clips::engine {

std::vector<std::shared_ptr<const assist::Request>> requests_for(const pddl::Task& task,
                                                                 const std::vector<inference::StepRecord>& steps,
                                                                 size_t hypotheses, inference::Modality m) {
  if (m == inference::Modality::ActionOnly) return std::vector<std::shared_ptr<const assist::Request>>(hypotheses);
  return assist::last_requests(task, steps, hypotheses);
}

std::vector<double> assistant_weights(const inference::Belief& belief, const inference::Posterior& post) {
  std::vector<double> w = post.hypotheses;
  const auto& hyps = belief.hypotheses();
  const auto& profiles = belief.profiles();
  for (size_t h = 0; h < w.size(); ++h) {
    const int base = profiles.at(static_cast<size_t>(hyps[h].profile)).twin_of;
    if (base < 0) continue;
    // The belief enumerates goal-major (goal g, profile c at g * |profiles| + c).
    const size_t k = static_cast<size_t>(hyps[h].goal) * profiles.size() + static_cast<size_t>(base);
    if (k >= hyps.size() || hyps[k].goal != hyps[h].goal || hyps[k].profile != base)
      throw std::logic_error("assistant_weights: the belief's hypotheses are not goal-major");
    w[k] += w[h];
    w[h] = 0;
  }
  return w;
}

std::vector<assist::Hypothesis> assistant_hypotheses(inference::Belief& belief, const inference::Posterior& post,
                                                     const std::vector<std::shared_ptr<const assist::Request>>& requests,
                                                     PolicyUse use) {
  std::vector<assist::Hypothesis> hyps;
  auto& policies = belief.policies();
  const std::vector<double> w = assistant_weights(belief, post);
  for (size_t h = 0; h < post.hypotheses.size(); ++h) {
    std::shared_ptr<search::Policy> p = use == PolicyUse::Copy
                                            ? std::make_shared<search::Policy>(policies[h])
                                            : std::shared_ptr<search::Policy>(&policies[h], [](search::Policy*) {});
    hyps.push_back({w[h], std::move(p), nullptr});
  }
  assist::attach_requests(hyps, requests);
  return hyps;
}

std::vector<assist::Hypothesis> assistant_hypotheses(const inference::Belief& belief, const inference::Posterior& post,
                                                     const std::vector<std::shared_ptr<const assist::Request>>& requests) {
  std::vector<assist::Hypothesis> hyps;
  const std::vector<double> w = assistant_weights(belief, post);
  for (size_t h = 0; h < post.hypotheses.size(); ++h)
    hyps.push_back({w[h], std::make_shared<search::Policy>(belief.policies()[h]), nullptr});
  assist::attach_requests(hyps, requests);
  return hyps;
}

}  // namespace clips::engine
