#pragma once
// The multimodal-LLM baseline (paper Table 1, "GPT-4V"): the state at the
// utterance is rendered as a PNG and sent, with the instruction and the
// domain's rules in text, to an OpenAI-compatible /v1/chat/completions
// endpoint. The model must answer with strict JSON
//   {"goal_probabilities": {"gem1": 0.7, ...}, "actions": ["(pickup robot key2)", ...]}
// The assistant then plays the parsed actions on its own turns (illegal or
// unknown ones are reported and replaced by a wait) in the episodes' one loop
// (assist::scripted_episode), with the simulated human of the other methods;
// once the list is used up the human finishes alone. Scored with the same
// metrics as the other methods.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "assist/assist.hpp"
#include "data/dataset.hpp"
#include "lm/http_client.hpp"
#include "lm/openai_chat.hpp"

namespace clips::multimodal {

// A malformed answer (not JSON, a missing or mistyped field, an unknown
// goal). The message names the field.
class MultimodalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MultimodalOptions {
  std::string base_url;                // "" -> $CLIPS_CHAT_BASE_URL, else the OpenAI API
  std::string model;                   // "" -> $CLIPS_CHAT_MODEL, else the client's default
  std::optional<std::string> api_key;  // nullopt -> $OPENAI_API_KEY
  lm::HttpOptions http;                // timeouts and retries
  int max_tokens = 600;
  int cell_px = 48;                    // picture size
  // True when an endpoint is given here or in $CLIPS_CHAT_BASE_URL (bench
  // runs the method only then).
  bool configured() const;
};

struct MultimodalAnswer {
  std::vector<double> goal_posterior;  // in the candidate goals' order, normalised
  std::vector<std::string> actions;    // as written by the model
  std::vector<std::string> notes;      // goals left out, renormalisation
};

// Strict parser of the model's answer. Throws MultimodalError.
MultimodalAnswer parse_multimodal_answer(const std::string& text, const std::vector<std::string>& goals);

// The domain's rules, in a few plain sentences.
std::string multimodal_rules(const domains::Pack& pack);

// The chat request for one plan (exposed for tests and logging).
lm::ChatRequest multimodal_request(const data::Dataset& ds, const data::PlanRecord& plan, const pddl::State& s_T,
                                   const std::vector<std::string>& goals, int cell_px = 48);

// Plays `actions` for the assistant from setup.start (see the file comment).
// `truth` is the true goal's policy; notes receive one line per skipped action.
assist::AssistResult execute_assistant_actions(const assist::AssistSetup& setup, const std::vector<std::string>& actions,
                                               search::Policy truth, std::vector<std::string>& notes);

struct MultimodalRun {
  MultimodalAnswer answer;
  assist::AssistResult result;
  std::vector<std::string> notes;  // the answer's notes, then the execution's
  std::string raw_answer;
};

// One plan end to end. Throws lm::LmError (transport) or MultimodalError.
MultimodalRun run_multimodal(const data::Dataset& ds, const data::PlanRecord& plan, const assist::AssistSetup& setup,
                             const std::vector<std::string>& goals, const search::Policy& truth,
                             const MultimodalOptions& options);

}  // namespace clips::multimodal
