#include "language/lm_domain.hpp"

#include <algorithm>

namespace clips::language {

lm::DomainDescription describe_for_language_model(const pddl::Domain& domain, const pddl::Problem& problem,
                                                  const commands::LanguageConfig& config,
                                                  const std::vector<std::string>& qualifier_predicates) {
  auto type_name = [&](pddl::TypeId t) { return domain.types[static_cast<size_t>(t)].name; };
  lm::DomainDescription out;
  for (const pddl::ActionSchema& a : domain.actions) {
    lm::DomainActionSchema s{a.name, {}};
    for (pddl::TypeId t : a.param_types) s.parameter_types.push_back(type_name(t));
    out.actions.push_back(std::move(s));
  }
  for (const pddl::TypeDef& t : domain.types)
    if (t.parent >= 0) out.parent_type[t.name] = type_name(t.parent);
  for (const pddl::ObjectDef& o : problem.objects) out.objects.push_back({o.name, type_name(o.type)});
  const std::vector<std::string> qualifiers =
      qualifier_predicates.empty() ? std::vector<std::string>{config.qualifier} : qualifier_predicates;
  const size_t object_arg = static_cast<size_t>(std::max(1, config.qualifier_object_arg) - 1);
  for (const pddl::InitAtom& atom : problem.init_atoms) {
    const std::string& name = domain.predicates[static_cast<size_t>(atom.pred)].name;
    if (atom.args.size() != 2 || std::find(qualifiers.begin(), qualifiers.end(), name) == qualifiers.end()) continue;
    const size_t value_arg = object_arg == 0 ? 1 : 0;
    out.qualifiers.push_back({name, problem.objects[static_cast<size_t>(atom.args[std::min<size_t>(object_arg, 1)])].name,
                              problem.objects[static_cast<size_t>(atom.args[value_arg])].name});
  }
  for (const pddl::InitAtom& atom : problem.init_atoms) {
    const std::string& name = domain.predicates[static_cast<size_t>(atom.pred)].name;
    if (atom.args.size() == 2 && config.is_location(name))
      out.locations.push_back({name, problem.objects[static_cast<size_t>(atom.args[0])].name,
                               problem.objects[static_cast<size_t>(atom.args[1])].name});
  }
  for (const commands::SalientActionRule& r : config.salient_actions)
    out.command_actions.push_back({r.action, r.agent_arg, r.focal_arg, config.destinations ? r.destination_arg : 0,
                                 r.focal_is_place});
  out.destination_predicate = commands::kDestinationPredicate;
  out.speaker = config.speaker;
  out.listener = config.listener;
  out.speaker_pronoun = config.speaker_pronoun;
  out.listener_pronoun = config.listener_pronoun;
  return out;
}

}  // namespace clips::language
