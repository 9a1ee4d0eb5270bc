#include "engine/json.hpp"

#include <cmath>

#include "engine/runs.hpp"
#include "inference/belief.hpp"

namespace clips::engine {

using nlohmann::json;

// The modality's name in the one table (inference/belief.hpp): "both", "utterance", "action".
std::string evidence_name(Method m) { return inference::to_string(modality_of(m)); }

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json to_json(const Posterior& p, Method m) {
  json goals = json::array(), profiles = json::array(), hyps = json::array();
  for (size_t g = 0; g < p.goals.size(); ++g) goals.push_back({{"goal", p.goals[g]}, {"p", p.goal_probabilities[g]}});
  for (size_t c = 0; c < p.cost_profiles.size(); ++c)
    profiles.push_back({{"cost_profile", p.cost_profiles[c]}, {"p", p.cost_profile_probabilities[c]}});
  for (const auto& h : p.hypotheses) hyps.push_back({{"goal", h.goal}, {"cost_profile", h.cost_profile}, {"p", h.weight}});
  return {{"method", method_name(m)},
          {"modality", evidence_name(m)},
          {"goals", std::move(goals)},
          {"cost_profiles", std::move(profiles)},
          {"hypotheses", std::move(hyps)},
          {"log_marginal_likelihood", number_or_null(p.log_marginal_likelihood)}};
}

json to_json(const Step& s, Method m) {
  return {{"t", s.t},
          {"action", s.action},
          {"agent", s.agent},
          {"evidence", s.evidence},
          {"utterances", s.utterances},
          {"utterance_warnings", s.utterance_warnings},
          {"posterior", to_json(s.posterior, m)},
          {"seconds", s.seconds}};
}

json to_json(const AssistDecision& d) {
  json j;
  j["method"] = d.method;
  j["assistant_turn"] = d.assistant_turn;
  j["action"] = d.assistant_turn ? json(d.action) : json(nullptr);
  j["id"] = d.id;
  j["reason"] = d.reason;
  j["unanimous"] = d.unanimous;
  json cands = json::array();
  for (const auto& c : d.candidates) cands.push_back({{"id", c.id}, {"action", c.action}, {"value", number_or_null(c.value)}});
  j["candidates"] = std::move(cands);
  if (!d.command.empty()) {
    j["command"] = d.command;
    j["command_probability"] = d.command_probability;
  }
  if (!d.request_command.empty()) {
    j["request"] = d.request_command;
    j["followed_request"] = d.followed_request;
  }
  j["goals"] = d.goals;
  j["goal_weights"] = d.goal_weights;
  return j;
}

}  // namespace clips::engine
