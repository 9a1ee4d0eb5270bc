#include "commands/command.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <stdexcept>

#include "util/numbered_names.hpp"

namespace clips::commands {

namespace {

std::string lowercase_first(std::string s) {
  if (!s.empty()) s.front() = static_cast<char>(std::tolower(static_cast<unsigned char>(s.front())));
  return s;
}

std::string uppercase_first(std::string s) {
  if (!s.empty()) s.front() = static_cast<char>(std::toupper(static_cast<unsigned char>(s.front())));
  return s;
}

std::string lowercase(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// How a variable is written in PDDL: PDDL.jl prints Var(:Key1) as ?key1.
std::string pddl_variable(const std::string& name) { return "?" + lowercase_first(name); }

// Renders a term, rewriting variable arguments with `render_var` (given the
// name without '?'); arguments for which `keep` is false are dropped.
template <class RenderVar, class Keep>
std::string render(const Term& term, RenderVar render_var, Keep keep) {
  std::string out = "(" + term.name;
  for (const auto& arg : term.args) {
    if (!keep(arg)) continue;
    out += ' ';
    out += is_variable(arg) ? render_var(arg.substr(1)) : arg;
  }
  return out + ")";
}

template <class RenderVar, class Keep>
std::string render_all(const std::vector<Term>& terms, RenderVar render_var, Keep keep) {
  std::string out;
  for (const auto& t : terms) {
    if (!out.empty()) out += ' ';
    out += render(t, render_var, keep);
  }
  return out;
}

std::string with_where(const std::string& actions, const std::string& predicates) {
  return predicates.empty() ? actions : actions + " where " + predicates;
}

const auto keep_all = [](const std::string&) { return true; };

}  // namespace

std::string Command::display_form() const {
  return with_where(render_all(actions, pddl_variable, keep_all),
                    render_all(predicates, pddl_variable, keep_all));
}

std::string Command::llm_form() const {
  const auto bare = [](const std::string& name) { return lowercase_first(name); };
  if (printed_form == PrintedForm::WhereClause)
    return util::mark_numbered(with_where(render_all(printed_actions.empty() ? actions : printed_actions, bare, keep_all),
                                    render_all(predicates, bare, keep_all)),
                         numbered);

  // VH: the item type is already in the variable name, so the qualifier
  // predicates and the variables they do not mention (fixtures) are dropped.
  std::vector<std::string> qualified;
  for (const auto& p : predicates)
    for (const auto& arg : p.args)
      if (is_variable(arg)) qualified.push_back(arg);
  const auto keep_qualified = [&](const std::string& arg) {
    return !is_variable(arg) || std::find(qualified.begin(), qualified.end(), arg) != qualified.end();
  };
  std::vector<Term> other_predicates;
  for (const auto& p : predicates)
    if (p.name != qualifier) other_predicates.push_back(p);
  return with_where(render_all(actions, bare, keep_qualified), render_all(other_predicates, bare, keep_all));
}

std::string Command::to_goal_formula(const LanguageConfig& config) const {
  // Goal atoms may be negated ("(not (locked $3))": what an action deletes).
  std::vector<Term> atoms;
  std::vector<bool> negated;
  for (const auto& action : actions) {
    const Term named = to_agent_names(action, config);
    auto it = config.goal_atoms.find(named.name);
    if (it == config.goal_atoms.end())
      throw std::invalid_argument("no goal atoms configured for action '" + named.name + "'");
    for (const auto& pattern : it->second) {
      // "(not (p ...))": the inner atom, negated.
      const std::size_t head = pattern.find_first_not_of(" \t(");
      const bool negative = pattern.compare(head == std::string::npos ? 0 : head, 4, "not ") == 0 ||
                            pattern.compare(head == std::string::npos ? 0 : head, 4, "not(") == 0;
      std::string text = pattern;
      if (negative) {
        const std::size_t open = pattern.find('(', head + 3);
        const std::size_t close = pattern.rfind(')');
        const std::size_t inner_close = close == std::string::npos ? close : pattern.rfind(')', close - 1);
        if (open == std::string::npos || inner_close == std::string::npos || inner_close <= open)
          throw std::invalid_argument("goal atom '" + pattern + "' is not (not (<predicate> ...))");
        text = pattern.substr(open, inner_close - open + 1);
      }
      Term atom = parse_term(text);
      for (auto& arg : atom.args) {
        if (arg.size() < 2 || arg.front() != '$') continue;
        const std::size_t index = std::stoul(arg.substr(1));
        if (index < 1 || index > named.args.size())
          throw std::invalid_argument("goal atom '" + pattern + "' refers to a missing argument of " +
                                      to_pddl(named));
        arg = named.args[index - 1];
        // VH quirk: ?Plate2 names the object plate2.
        if (config.goal_variables == GoalVariables::LowercasedName && is_variable(arg))
          arg = lowercase(arg.substr(1));
      }
      atoms.push_back(std::move(atom));
      negated.push_back(negative);
    }
  }
  auto render_atoms = [&] {
    std::string out;
    for (std::size_t i = 0; i < atoms.size(); ++i) {
      const std::string a = render(atoms[i], pddl_variable, keep_all);
      out += (out.empty() ? "" : " ") + (negated[i] ? "(not " + a + ")" : a);
    }
    return out;
  };

  const auto mentions_variable = [](const Term& t) {
    return std::any_of(t.args.begin(), t.args.end(), [](const std::string& a) { return is_variable(a); });
  };
  const bool lifted = !variables.empty() && std::any_of(atoms.begin(), atoms.end(), mentions_variable);
  if (!lifted) return "(and " + render_atoms() + ")";

  // Only the variables the goal atoms or qualifiers mention are quantified: a
  // destination cell of a put names no goal atom, and quantifying it would
  // only multiply the expansion by the cells (millions of instances on a
  // grid) for a formula that means the same (the paper's packs mention every
  // variable, so their formulas are unchanged).
  std::vector<Term> qualifiers;
  for (const auto& p : predicates)
    if (mentions_variable(p)) qualifiers.push_back(p);
  const auto mentioned = [&](const std::string& name) {
    const std::string var = "?" + name;
    const auto in = [&](const Term& t) { return std::find(t.args.begin(), t.args.end(), var) != t.args.end(); };
    return std::any_of(atoms.begin(), atoms.end(), in) || std::any_of(qualifiers.begin(), qualifiers.end(), in);
  };
  std::vector<const Variable*> quantified;
  for (const auto& v : variables)
    if (mentioned(v.name)) quantified.push_back(&v);
  std::string typed;
  for (const Variable* v : quantified) typed += (typed.empty() ? "" : " ") + pddl_variable(v->name) + " - " + v->type;
  std::string body = render_atoms();
  for (std::size_t i = 0; i < quantified.size(); ++i)
    for (std::size_t j = i + 1; j < quantified.size(); ++j)
      body += " (not (= " + pddl_variable(quantified[i]->name) + " " + pddl_variable(quantified[j]->name) + "))";
  for (const auto& p : qualifiers) body += " " + render(p, pddl_variable, keep_all);
  return "(exists (" + typed + ") (and " + body + "))";
}

Command lift_command(const std::vector<SalientAction>& subset, const LanguageConfig& config,
                     const TypeLookup& type_of) {
  if (!type_of) throw std::invalid_argument("lift_command needs an object-type lookup");
  const auto object_index = static_cast<std::size_t>(config.qualifier_object_arg - 1);

  // The qualifier value of an object within this command, e.g. "plate".
  const auto qualifier_value = [&](const std::string& object) -> std::optional<std::string> {
    for (const auto& s : subset)
      for (const auto& p : s.predicates) {
        if (p.name != config.qualifier || object_index >= p.args.size() || p.args[object_index] != object)
          continue;
        for (std::size_t i = 0; i < p.args.size(); ++i)
          if (i != object_index) return p.args[i];
      }
    return std::nullopt;
  };

  Command cmd;
  cmd.printed_form = config.printed_form;
  cmd.qualifier = config.qualifier;
  std::map<std::string, std::string> variable_of;  // object -> variable name
  std::map<std::string, int> count_of;             // name stem -> variables so far

  const auto variable_for = [&](const std::string& object) -> std::string {
    if (auto it = variable_of.find(object); it != variable_of.end()) return it->second;
    const std::string type = type_of(object);
    std::string stem = type;
    if (config.variable_naming == VariableNaming::QualifierValue)
      if (auto value = qualifier_value(object)) stem = *value;
    const int k = ++count_of[stem];
    std::string name = (config.variable_naming == VariableNaming::QualifierValue ? uppercase_first(stem) : stem) +
                       std::to_string(k);
    variable_of.emplace(object, name);
    cmd.variables.push_back({name, type});
    cmd.binding.push_back({name, object});
    return name;
  };

  // A named place whose number people say (LanguageConfig::numbered_names).
  const auto note_numbered = [&](const std::string& name) {
    if (std::binary_search(config.numbered_names.begin(), config.numbered_names.end(), name) &&
        std::find(cmd.numbered.begin(), cmd.numbered.end(), name) == cmd.numbered.end())
      cmd.numbered.push_back(name);
  };
  for (const auto& s : subset) {
    Term action{s.action.name, {}}, printed{s.action.name, {}};
    const SalientActionRule* rule = config.salient_rule(s.action.name);
    for (std::size_t i = 0; i < s.action.args.size(); ++i) {
      const std::string& arg = s.action.args[i];
      const std::string pronoun = config.to_pronoun(arg);
      const bool is_agent = pronoun != arg || config.is_pronoun(arg);
      const bool focal = rule && static_cast<int>(i) + 1 == rule->focal_arg;
      if (is_agent || is_variable(arg)) {
        action.args.push_back(pronoun);
      } else if (focal && rule->focal_is_place) {
        action.args.push_back(arg);
        note_numbered(arg);
      }
      else {
        action.args.push_back("?" + variable_for(arg));
      }
      if (is_agent || focal) printed.args.push_back(action.args.back());
    }
    cmd.actions.push_back(std::move(action));
    if (config.print_agents_and_focal_only) cmd.printed_actions.push_back(std::move(printed));
  }
  for (const auto& s : subset)
    for (const auto& p : s.predicates) {
      Term lifted{p.name, {}};
      const bool location = config.names_place(p.name);  // the place keeps its name: (on ?plank1 rack)
      for (std::size_t i = 0; i < p.args.size(); ++i) {
        const std::string& arg = p.args[i];
        auto it = variable_of.find(arg);
        const bool named = it == variable_of.end() || (location && i > 0);
        lifted.args.push_back(named ? arg : "?" + it->second);
        if (named) note_numbered(arg);
      }
      cmd.predicates.push_back(std::move(lifted));
    }
  return cmd;
}

Command merge_commands(const Command& first, const Command& second) {
  Command merged = first;
  const auto append_unique = [](std::vector<Term>& to, const std::vector<Term>& from) {
    std::vector<Term> out;
    for (const std::vector<Term>* list : {static_cast<const std::vector<Term>*>(&to), &from})
      for (const auto& t : *list)
        if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
    to = std::move(out);
  };
  append_unique(merged.actions, second.actions);
  append_unique(merged.printed_actions, second.printed_actions);
  append_unique(merged.predicates, second.predicates);
  for (const auto& n : second.numbered)
    if (std::find(merged.numbered.begin(), merged.numbered.end(), n) == merged.numbered.end()) merged.numbered.push_back(n);
  for (const auto& v : second.variables) {
    auto it = std::find_if(merged.variables.begin(), merged.variables.end(),
                           [&](const Variable& m) { return m.name == v.name; });
    if (it == merged.variables.end())
      merged.variables.push_back(v);
    else
      it->type = v.type;  // a dictionary merge: the later entry wins
  }
  for (const auto& b : second.binding) {
    const bool known = std::any_of(merged.binding.begin(), merged.binding.end(),
                                   [&](const Binding& m) { return m.variable == b.variable; });
    if (!known) merged.binding.push_back(b);
  }
  return merged;
}

Term substitute(const Term& term, const std::vector<Binding>& binding) {
  Term out = term;
  for (auto& arg : out.args) {
    if (!is_variable(arg)) continue;
    for (const auto& b : binding)
      if (arg.compare(1, std::string::npos, b.variable) == 0) {
        arg = b.object;
        break;
      }
  }
  return out;
}

std::vector<Term> substitute(const std::vector<Term>& terms, const std::vector<Binding>& binding) {
  std::vector<Term> out;
  out.reserve(terms.size());
  for (const auto& t : terms) out.push_back(substitute(t, binding));
  return out;
}

Term to_agent_names(const Term& term, const LanguageConfig& config) {
  Term out = term;
  for (auto& arg : out.args) arg = config.to_agent_name(arg);
  return out;
}

}  // namespace clips::commands
