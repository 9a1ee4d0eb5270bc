#include "assist/request.hpp"

namespace clips::assist {

std::vector<std::shared_ptr<const Request>> requests_from(const pddl::Task& task,
                                                          const inference::UtteranceRecord& record) {
  std::vector<std::shared_ptr<const Request>> out;
  out.reserve(record.hypotheses.size());
  auto ground = [&](const std::vector<std::string>& texts, std::vector<pddl::ActionId>& ids) {
    for (const std::string& t : texts) {
      auto a = task.find_action(t);
      if (!a) return false;  // not a ground action of this task: the command cannot be carried out as said
      ids.push_back(*a);
    }
    return true;
  };
  for (const inference::HypothesisUtterance& h : record.hypotheses) {
    auto req = std::make_shared<Request>();
    for (const inference::CommandScore& c : h.requests.empty() ? h.commands : h.requests) {
      if (!(c.posterior > 0)) continue;
      RequestedCommand rc;
      rc.probability = c.posterior;
      rc.text = c.command;
      if (!ground(c.listener_actions, rc.assistant_part) || !ground(c.speaker_actions, rc.principal_part)) continue;
      req->push_back(std::move(rc));
    }
    out.push_back(req->empty() ? nullptr : std::move(req));
  }
  return out;
}

std::vector<std::shared_ptr<const Request>> last_requests(const pddl::Task& task,
                                                          const std::vector<inference::StepRecord>& steps,
                                                          size_t hypotheses) {
  for (auto it = steps.rbegin(); it != steps.rend(); ++it)
    if (!it->utterances.empty()) {
      auto r = requests_from(task, it->utterances.back());
      r.resize(hypotheses);
      return r;
    }
  return std::vector<std::shared_ptr<const Request>>(hypotheses);
}

void attach_requests(std::vector<Hypothesis>& hyps, const std::vector<std::shared_ptr<const Request>>& requests) {
  for (size_t h = 0; h < hyps.size() && h < requests.size(); ++h) hyps[h].request = requests[h];
}

void set_request_rule(AssistSetup& setup, AssistRule rule, const commands::LanguageConfig& language) {
  setup.rule = rule;
  setup.impatient_principal = rule == AssistRule::Request;
  setup.restless_assistant = rule == AssistRule::Request;
  setup.trusts_own_plan = rule == AssistRule::Request;
  setup.salient_args = salient_argument_table(*setup.task, language);
}

}  // namespace clips::assist
