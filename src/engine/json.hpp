#pragma once
// The one JSON form of the engine's nouns (docs/decisions.md, "One posterior
// serializer"): the server's replies, `clips infer --json`, `clips assist
// --json` and Python's dicts (converted from this JSON) write posteriors,
// steps and decisions with these.
//
//   posterior  {"method": "clips", "modality": "both",
//               "goals": [{"goal": "gem1", "p": 0.25}, ...],
//               "cost_profiles": [{"cost_profile": "C3", "p": 0.5}, ...],
//               "hypotheses": [{"goal": "gem1", "cost_profile": "C3", "p": 0.125}, ...],
//               "log_marginal_likelihood": -3.2}            (null for -inf)
//   step       {"t", "action", "agent", "evidence", "utterances", "posterior", "seconds"}
//   decision   {"method", "assistant_turn", "action", "id", "reason", "unanimous",
//               "candidates": [{"id", "action", "value"}], "goals", "goal_weights"}
//               (+ "command", "command_probability" for literal; + "request",
//               "followed_request" when Q_MDP's request rule acted on one)
#include <nlohmann/json.hpp>

#include "clips/types.hpp"

namespace clips::engine {

// The evidence a method's posterior uses, by its older name ("both",
// "utterance", "action"), which the web page shows.
std::string evidence_name(Method m);
// JSON has no infinity: dead ends and impossible evidence are null.
nlohmann::json number_or_null(double v);

nlohmann::json to_json(const Posterior& p, Method m);
nlohmann::json to_json(const Step& s, Method m);
nlohmann::json to_json(const AssistDecision& d);

}  // namespace clips::engine
