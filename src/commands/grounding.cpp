#include "commands/grounding.hpp"

#include <algorithm>
#include <optional>
#include <set>

namespace clips::commands {

namespace {

void push_unique(std::vector<std::string>& list, const std::string& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

// Binds the variables of `pattern` so that it equals `ground`, or nothing.
std::optional<std::vector<Binding>> unify(const Term& pattern, const Term& ground) {
  if (pattern.name != ground.name || pattern.args.size() != ground.args.size()) return std::nullopt;
  std::vector<Binding> binding;
  for (std::size_t i = 0; i < pattern.args.size(); ++i) {
    const std::string& p = pattern.args[i];
    if (!is_variable(p)) {
      if (p != ground.args[i]) return std::nullopt;
      continue;
    }
    const std::string name = p.substr(1);
    auto it = std::find_if(binding.begin(), binding.end(), [&](const Binding& b) { return b.variable == name; });
    if (it == binding.end())
      binding.push_back({name, ground.args[i]});
    else if (it->object != ground.args[i])
      return std::nullopt;
  }
  return binding;
}

}  // namespace

std::vector<GroundCommand> naive_groundings(const Command& command,
                                            const std::map<std::string, std::vector<std::string>>& objects_by_type,
                                            const std::vector<Term>& facts) {
  if (command.variables.empty()) return {GroundCommand{command.actions, command.predicates, {}}};

  const std::set<Term> fact_set(facts.begin(), facts.end());
  const std::size_t n = command.variables.size();
  // A predicate can be tested once the last variable it mentions is bound.
  std::vector<std::vector<const Term*>> checks_after(n);
  for (const auto& p : command.predicates) {
    std::size_t last = 0;
    for (const auto& arg : p.args)
      for (std::size_t v = 0; v < n; ++v)
        if (is_variable(arg) && arg.compare(1, std::string::npos, command.variables[v].name) == 0)
          last = std::max(last, v);
    checks_after[last].push_back(&p);
  }

  std::vector<GroundCommand> result;
  std::vector<std::pair<std::set<Term>, std::set<Term>>> seen;  // set identity of each kept grounding
  std::vector<Binding> binding;
  const auto extend = [&](auto&& self, std::size_t v) -> void {
    if (v == n) {
      GroundCommand g{substitute(command.actions, binding), substitute(command.predicates, binding), binding};
      std::pair<std::set<Term>, std::set<Term>> key{{g.actions.begin(), g.actions.end()},
                                                    {g.predicates.begin(), g.predicates.end()}};
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;
      seen.push_back(std::move(key));
      result.push_back(std::move(g));
      return;
    }
    auto objects = objects_by_type.find(command.variables[v].type);
    if (objects == objects_by_type.end()) return;
    for (const auto& object : objects->second) {
      const bool used = std::any_of(binding.begin(), binding.end(), [&](const Binding& b) { return b.object == object; });
      if (used) continue;
      binding.push_back({command.variables[v].name, object});
      const bool holds = std::all_of(checks_after[v].begin(), checks_after[v].end(), [&](const Term* p) {
        return fact_set.contains(substitute(*p, binding));
      });
      if (holds) self(self, v + 1);
      binding.pop_back();
    }
  };
  extend(extend, 0);
  return result;
}

std::vector<std::string> focal_objects(const std::vector<Term>& actions, const LanguageConfig& config) {
  std::vector<std::string> objects;
  for (const auto& action : actions) {
    const SalientActionRule* rule = config.salient_rule(action.name);
    if (rule == nullptr || rule->focal_arg > static_cast<int>(action.args.size())) continue;
    push_unique(objects, action.args[rule->focal_arg - 1]);
  }
  return objects;
}

std::vector<std::string> match_focal_objects(const Command& command, const std::vector<Term>& plan,
                                             const LanguageConfig& config) {
  std::vector<std::string> focal_variables, named;  // named: focal objects the command names (places)
  for (const auto& arg : focal_objects(command.actions, config)) {
    if (is_variable(arg))
      focal_variables.push_back(arg.substr(1));
    else
      named.push_back(arg);
  }

  std::vector<std::string> objects;
  for (const auto& lifted : command.actions) {
    const Term pattern = to_agent_names(lifted, config);
    for (const auto& action : plan) {
      auto binding = unify(pattern, action);
      if (!binding) continue;
      for (const auto& var : focal_variables)
        for (const auto& b : *binding)
          if (b.variable == var) push_unique(objects, b.object);
      for (const auto& object : named)
        if (std::find(lifted.args.begin(), lifted.args.end(), object) != lifted.args.end()) push_unique(objects, object);
    }
  }
  return objects;
}

}  // namespace clips::commands
