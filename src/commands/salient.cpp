#include "commands/salient.hpp"

#include <stdexcept>

namespace clips::commands {

std::vector<SalientAction> extract_salient(const std::vector<Term>& actions, const LanguageConfig& config,
                                           const QualifierLookup& qualifier_of) {
  std::vector<SalientAction> salient;
  for (const auto& action : actions) {
    const SalientActionRule* rule = config.salient_rule(action.name);
    if (rule == nullptr) continue;
    const auto arity = static_cast<int>(action.args.size());
    if (rule->agent_arg > arity || rule->focal_arg > arity)
      throw std::invalid_argument("salient action " + to_pddl(action) + " has too few arguments");
    SalientAction s{action, action.args[rule->agent_arg - 1], action.args[rule->focal_arg - 1], {}};
    if (qualifier_of)
      for (auto& q : qualifier_of(s.focal)) s.predicates.push_back(std::move(q));
    salient.push_back(std::move(s));
  }
  return salient;
}

QualifierLookup qualifier_lookup_from_facts(std::vector<Term> facts, const LanguageConfig& config) {
  return [facts = std::move(facts), names = config.qualifiers(),
          index = static_cast<std::size_t>(config.qualifier_object_arg - 1)](const std::string& object) {
    // The first fact of each qualifier predicate, in the config's order.
    std::vector<Term> out;
    for (const auto& name : names)
      for (const auto& fact : facts)
        if (fact.name == name && index < fact.args.size() && fact.args[index] == object) {
          out.push_back(fact);
          break;
        }
    return out;
  };
}

}  // namespace clips::commands
