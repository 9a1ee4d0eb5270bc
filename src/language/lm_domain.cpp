#include "language/lm_domain.hpp"

#include <algorithm>

#include "lm/wordnet_lexicon.hpp"
#include "util/numbered_names.hpp"

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
    if (atom.args.size() == 2 && config.is_location(name) &&
        lm::WordNetLexicon::instance().sayable_name(problem.objects[static_cast<size_t>(atom.args[1])].name))
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
  out.numbered = numbered_place_names(domain, problem, config);
  return out;
}

std::vector<std::string> numbered_place_names(const pddl::Domain& domain, const pddl::Problem& problem,
                                              const commands::LanguageConfig& config) {
  // The types commands lift: the focal parameters of salient actions that
  // are not about a place, and the agents.
  std::vector<pddl::TypeId> lifted;
  for (const commands::SalientActionRule& r : config.salient_actions) {
    if (r.focal_is_place) continue;
    for (const pddl::ActionSchema& a : domain.actions) {
      if (a.name != r.action) continue;
      if (r.focal_arg >= 1 && r.focal_arg <= static_cast<int>(a.param_types.size()))
        lifted.push_back(a.param_types[static_cast<size_t>(r.focal_arg - 1)]);
      if (r.agent_arg >= 1 && r.agent_arg <= static_cast<int>(a.param_types.size()))
        lifted.push_back(a.param_types[static_cast<size_t>(r.agent_arg - 1)]);
    }
  }
  std::vector<std::string> names;
  for (const pddl::ObjectDef& o : problem.objects) {
    const bool is_lifted = std::any_of(lifted.begin(), lifted.end(),
                                       [&](pddl::TypeId t) { return domain.is_subtype(o.type, t); });
    if (!is_lifted && o.name != config.speaker && o.name != config.listener) names.push_back(o.name);
  }
  return util::numbered_names(names);
}

}  // namespace clips::language
