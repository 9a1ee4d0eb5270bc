#pragma once
// What the principal asked for, as the assistant reads it from the belief:
// per hypothesis, the commands its speaker model explains the last
// instruction with (P(c | u, s, h)), grounded to the task's actions. Q_MDP's
// request rule (AssistRule::Request) breaks ties between equally good
// actions with it.
#include <memory>
#include <vector>

#include "assist/assist.hpp"
#include "inference/belief.hpp"

namespace clips::assist {

// One request per hypothesis (null where the record has no command for it)
// from the last utterance of `record`.
std::vector<std::shared_ptr<const Request>> requests_from(const pddl::Task& task,
                                                          const inference::UtteranceRecord& record);
// The same from the last step of `steps` that heard an utterance; all null
// when none did.
std::vector<std::shared_ptr<const Request>> last_requests(const pddl::Task& task,
                                                          const std::vector<inference::StepRecord>& steps,
                                                          size_t hypotheses);

// Attaches them to the assistant's hypotheses (same order as the belief's).
void attach_requests(std::vector<Hypothesis>& hyps, const std::vector<std::shared_ptr<const Request>>& requests);

// The request rule's settings for a task and the pack's command language:
// AssistSetup::rule and AssistSetup::salient_args.
void set_request_rule(AssistSetup& setup, AssistRule rule, const commands::LanguageConfig& language);

}  // namespace clips::assist
