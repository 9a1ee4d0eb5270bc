#include "engine/hypotheses.hpp"

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
  for (size_t h = 0; h < w.size(); ++h) {
    const size_t base = static_cast<size_t>(belief.base_of(h));
    if (base == h) continue;
    w[base] += w[h];
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
