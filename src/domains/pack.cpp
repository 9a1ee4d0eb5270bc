// The generic behaviour of a pack: everything derived from its PackSpec.
#include "domains/pack.hpp"
#include "domains/task_transform.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "domains/strips.hpp"
#include "pddl/sexpr.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"

namespace clips::domains {

namespace fs = std::filesystem;

Pack::Pack(PackSpec spec) : spec_(std::move(spec)) {}

void Pack::check_problem(const pddl::Task&, const std::string&) const {}

void Pack::check_observed_plan(const pddl::PlanFile& obs) const {
  const int most = spec_.max_utterances_per_plan;
  const int n = static_cast<int>(obs.utterances.size());
  if (most <= 0 || n <= most) return;
  const auto& extra = obs.utterances[static_cast<size_t>(most)];
  if (most == 1)
    throw InputError(extra.loc, "a second utterance; a " + spec_.name + " observed plan has at most one ';' line (the "
                                "first is at line " + std::to_string(obs.utterances[0].loc.line) + ")");
  throw InputError(extra.loc, "utterance " + std::to_string(most + 1) + "; a " + spec_.name +
                                  " observed plan has at most " + std::to_string(most) + " ';' lines");
}

void Pack::check_plan_tag(const std::string& tag, const std::string& plan_id) const {
  if (spec_.plan_tags.empty()) return;
  if (std::find(spec_.plan_tags.begin(), spec_.plan_tags.end(), tag) != spec_.plan_tags.end()) return;
  std::string known;
  for (const auto& t : spec_.plan_tags) known += (known.empty() ? "" : " or ") + t;
  throw InputError("plan " + plan_id + ": condition must be " + known + ", got '" + tag + "'");
}

// ---- goals --------------------------------------------------------------------

std::vector<GoalSpec> Pack::problem_goals(const pddl::Task& task, const std::string& problem_path) const {
  std::vector<GoalSpec> out;
  if (spec_.goals.source == GoalSource::Objects) {
    const std::string& tpl = spec_.goals.condition;
    const size_t at = tpl.find("{}");
    for (pddl::ObjectId o : task.objects_of_type(spec_.goals.object_type)) {
      const std::string& name = task.object_name(o);
      out.push_back({name, tpl.substr(0, at) + name + tpl.substr(at + 2), ""});
    }
    if (out.empty())
      throw InputError(SourceLoc{problem_path, 0, 0}, "no object of type '" + spec_.goals.object_type +
                                                          "', so no candidate goal (pack " + spec_.name +
                                                          ": goals.object_type)");
    return out;
  }
  if (spec_.goals.source == GoalSource::ProblemGoal) {
    if (!task.problem().goal_sexpr)
      throw InputError(SourceLoc{problem_path, 0, 0},
                       "the problem has no :goal, and pack " + spec_.name + " takes its candidate goal from there");
    out.push_back({"goal", task.problem().goal_sexpr->str(), problem_path});
    return out;
  }
  throw InputError("pack " + spec_.name + ": goal sets are files of a dataset (goals/sets/), not of a problem");
}

namespace {

// The atoms of a conjunction (or the one atom), as text.
std::set<std::string> atoms_of(const std::string& text) {
  auto e = pddl::read_one_sexpr(text, "goal");
  std::set<std::string> out;
  if (e.head() == "and")
    for (size_t i = 1; i < e.items.size(); ++i) out.insert(e.items[i].str());
  else
    out.insert(e.str());
  return out;
}

}  // namespace

int reached_goal_index(const pddl::Task& task, const std::vector<GoalSpec>& goals, const pddl::PlanFile& observed,
                       const pddl::PlanFile& completed) {
  auto obs = pddl::simulate(task, task.initial_state(), observed);
  auto comp = pddl::simulate(task, obs.states.back(), completed);
  std::vector<int> reached;
  for (size_t i = 0; i < goals.size(); ++i) {
    auto g = task.compile_text(goals[i].condition, goals[i].source.empty() ? "goal " + goals[i].label : goals[i].source);
    if (g.holds(comp.states.back())) reached.push_back(static_cast<int>(i));
  }
  // Goals may nest (juice1 is a part of juice2): the most demanding one reached is meant.
  std::vector<int> maximal;
  for (int i : reached) {
    const auto a = atoms_of(goals[i].condition);
    bool part = false;
    for (int j : reached) {
      if (j == i) continue;
      const auto b = atoms_of(goals[j].condition);
      if (b.size() > a.size() && std::includes(b.begin(), b.end(), a.begin(), a.end())) part = true;
    }
    if (!part) maximal.push_back(i);
  }
  if (maximal.size() == 1) return maximal[0];
  std::string names;
  for (int i : maximal) names += " " + goals[i].label;
  throw InputError("completion reaches " + std::to_string(maximal.size()) +
                   " candidate goals (expected exactly 1):" + (names.empty() ? " none" : names));
}

int Pack::true_goal_index(const pddl::Task& task, const std::vector<GoalSpec>& goals, const std::string& tag,
                          const pddl::PlanFile& observed, const pddl::PlanFile& completed) const {
  switch (spec_.goals.true_goal) {
    case TrueGoalRule::PlanTag: {
      for (size_t i = 0; i < goals.size(); ++i)
        if (goals[i].label == tag) return static_cast<int>(i);
      std::string known;
      for (const auto& g : goals) known += (known.empty() ? "" : ", ") + g.label;
      throw InputError(SourceLoc{observed.path, 0, 0},
                       "the plan's goal label '" + tag + "' is not a candidate goal of its problem (" + known + ")");
    }
    case TrueGoalRule::LastActionObject: {
      if (completed.actions.empty()) throw InputError(SourceLoc{completed.path, 0, 0}, "completed plan is empty");
      const auto& last = completed.actions.back();
      auto e = pddl::read_one_sexpr(last.text, last.loc.file);
      for (size_t k = e.items.size(); k-- > 1;)
        for (size_t i = 0; i < goals.size(); ++i)
          if (goals[i].label == e.items[k].atom) return static_cast<int>(i);
      throw InputError(last.loc, "the completed plan's last action " + last.text +
                                     " names no candidate goal (pack " + spec_.name + ": goals.true_goal)");
    }
    case TrueGoalRule::CompletionReaches: return reached_goal_index(task, goals, observed, completed);
  }
  return 0;
}

// ---- costs ----------------------------------------------------------------------

model::CostProfile Pack::default_profile() const {
  const double effort = spec_.roles.principal_effort;
  if (spec_.roles.noop_cost == 1.0 && effort == 1.0) return model::unit_profile();
  model::CostProfile p = model::unit_profile();
  p.name = "default";
  for (const std::string& agent : {spec_.roles.principal, spec_.roles.assistant})
    p.costs[{agent, spec_.roles.noop_action}] = spec_.roles.noop_cost;
  if (effort != 1.0) {
    p.effort_factors[spec_.roles.principal] = effort;
    p.noop_action = spec_.roles.noop_action;
  }
  return p;
}

ProfileSet Pack::profiles_for(const std::string& tag) const {
  ProfileSet set = declared_profiles_for(tag);
  if (spec_.inference.alone_cost_factor > 0) {
    const size_t n = set.profiles.size();
    for (size_t i = 0; i < n; ++i)
      set.profiles.push_back(model::alone_twin(set.profiles[i], static_cast<int>(i), spec_.roles.assistant,
                                               spec_.roles.noop_action, spec_.inference.alone_cost_factor));
  }
  return set;
}

ProfileSet Pack::declared_profiles_for(const std::string& tag) const {
  if (spec_.cost_profiles.empty()) return {{default_profile()}, 0};
  const ProfileRule* fallback = nullptr;
  for (const auto& r : spec_.cost_profiles) {
    if (r.tag == tag) return {r.profiles, r.true_index};
    if (r.tag.empty()) fallback = &r;
  }
  // A live session has no tag: the untagged rule, else the first.
  if (!fallback && tag.empty()) fallback = &spec_.cost_profiles.front();
  if (fallback) return {fallback->profiles, fallback->true_index};
  std::string known;
  for (const auto& r : spec_.cost_profiles) known += (known.empty() ? "" : ", ") + r.tag;
  throw InputError("pack " + spec_.name + " has no cost profiles for plans tagged '" + tag + "' (tags: " + known + ")");
}

model::CostProfile Pack::cost_profile(const std::string& which) const {
  if (which == "unit") return model::unit_profile();
  if (which == "task") return model::task_costs_profile();
  if (which == "default" && spec_.cost_profiles.empty()) return default_profile();
  std::vector<std::string> names;
  for (const auto& r : spec_.cost_profiles)
    for (const auto& p : r.profiles) {
      if (p.name == which) return p;
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
    }
  if (which.empty()) return model::unit_profile();
  // "<name>-alone": the alone twin of a profile (its base is linked by
  // model::link_alone_twins when both are in one set).
  const std::string suffix = model::kAloneSuffix;
  if (spec_.inference.alone_cost_factor > 0 && which.size() > suffix.size() &&
      which.compare(which.size() - suffix.size(), suffix.size(), suffix) == 0) {
    const model::CostProfile base = cost_profile(which.substr(0, which.size() - suffix.size()));
    return model::alone_twin(base, -1, spec_.roles.assistant, spec_.roles.noop_action,
                             spec_.inference.alone_cost_factor);
  }
  std::string known = spec_.cost_profiles.empty() ? "unit, task, default" : "unit, task";
  for (const auto& n : names) known += ", " + n;
  if (spec_.inference.alone_cost_factor > 0) known += " (each also as <name>-alone)";
  throw InputError("--costs '" + which + "' is not a cost profile of " + spec_.name + " (known: " + known + ")");
}

// ---- heuristics ------------------------------------------------------------------

std::vector<std::string> Pack::heuristic_names() const {
  std::vector<std::string> names = {default_admissible_heuristic()};
  std::vector<std::string> rest = own_heuristics() ? own_heuristics()->names() : std::vector<std::string>{};
  for (const auto& n : heuristics::generic_heuristic_choices().names()) rest.push_back(n);
  for (const auto& n : rest)
    if (n != names.front()) names.push_back(n);
  return names;
}

std::unique_ptr<heuristics::Heuristic> Pack::make_heuristic(const std::string& name, const pddl::Task& task) const {
  if (const auto* own = own_heuristics(); own && own->contains(name)) return own->parse(name)(task);
  const auto& generic = heuristics::generic_heuristic_choices();
  if (generic.contains(name)) return generic.parse(name)(task);
  throw InputError("unknown heuristic '" + name + "' for " + spec_.name + " (known: " +
                   util::or_list(heuristic_names()) + ")");
}

// ---- language -------------------------------------------------------------------

std::vector<commands::FewShotExample> Pack::fewshot(bool literal, const std::string& language_dir) const {
  const FewShotSource& src = spec_.fewshot;
  const std::vector<int>& declared = literal ? src.literal_order : src.pragmatic_order;
  std::vector<commands::FewShotExample> all;
  if (!src.file.empty()) {
    fs::path file(src.file);
    if (file.is_relative() && !spec_.source.empty()) file = fs::path(spec_.source).parent_path() / file;
    all = commands::load_fewshot_examples(file);
    if (!declared.empty()) return commands::order_examples(all, src.domain, declared);
    std::vector<commands::FewShotExample> out;
    for (auto& e : all)
      if (e.domain == src.domain && (!literal || e.in_literal_prompt)) out.push_back(e);
    if (out.empty())
      throw InputError(SourceLoc{file.string(), 0, 0}, "no few-shot example for domain '" + src.domain + "'" +
                                                           (literal ? " marked for the literal prompt" : ""));
    return out;
  }
  const std::string dir = language_dir.empty() ? util::data_path("language") : language_dir;
  all = commands::load_fewshot_examples(dir + "/fewshot-examples.tsv");
  if (!declared.empty()) return commands::order_examples(all, src.domain, declared);
  const auto orders = commands::load_prompt_orders(dir + "/prompt-orders.json");
  const auto it = orders.find(src.domain);
  if (it != orders.end()) return commands::order_examples(all, src.domain, literal ? it->second.literal : it->second.pragmatic);
  std::vector<commands::FewShotExample> out;
  for (auto& e : all)
    if (e.domain == src.domain && (!literal || e.in_literal_prompt)) out.push_back(e);
  return out;  // may be empty: the model then works from its generated corpus alone
}

// ---- literal listener --------------------------------------------------------------

std::vector<commands::Term> Pack::literal_candidates(const pddl::Task& task, const pddl::State&) const {
  std::vector<commands::Term> out;
  const auto& cfg = spec_.language;
  for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
    const auto& ga = task.action(a);
    const std::string& name = task.domain().actions[ga.schema].name;
    const auto* rule = cfg.salient_rule(name);
    if (!rule || rule->agent_arg < 1 || rule->agent_arg > static_cast<int>(ga.args.size())) continue;
    if (task.object_name(ga.args[rule->agent_arg - 1]) != cfg.listener) continue;
    commands::Term t{name, {}};
    for (auto o : ga.args) t.args.push_back(task.object_name(o));
    out.push_back(std::move(t));
  }
  return out;
}

QualifierOf Pack::qualifier_of(const pddl::Task& task) const {
  const auto& cfg = spec_.language;
  // Static facts only: a qualifier describes what an object is.
  auto facts = std::make_shared<std::map<std::string, std::vector<commands::Term>>>();
  const int obj = cfg.qualifier_object_arg == 2 ? 1 : 0;
  for (const std::string& name : cfg.qualifiers()) {
    auto pred = task.domain().find_predicate(name);
    if (!pred || task.domain().predicates[*pred].arg_types.size() != 2) continue;
    const auto& types = task.domain().predicates[*pred].arg_types;
    std::set<std::string> done;  // one value per object and predicate
    for (pddl::ObjectId a = 0; a < task.num_objects(); ++a) {
      if (!task.domain().is_subtype(task.problem().objects[a].type, types[0])) continue;
      for (pddl::ObjectId b = 0; b < task.num_objects(); ++b) {
        if (!task.domain().is_subtype(task.problem().objects[b].type, types[1])) continue;
        auto ref = task.atom(*pred, {a, b});
        if (ref.bit >= 0 || !ref.value) continue;
        const std::string object = task.object_name(obj == 0 ? a : b);
        if (!done.insert(object).second) continue;
        (*facts)[object].push_back(commands::Term{name, {task.object_name(a), task.object_name(b)}});
      }
    }
  }
  return [facts](const std::string& object) -> std::vector<commands::Term> {
    auto it = facts->find(object);
    return it == facts->end() ? std::vector<commands::Term>{} : it->second;
  };
}

std::function<bool(const std::string&)> Pack::goal_unsatisfiable(const pddl::Task&) const { return {}; }

// ---- assistance options -------------------------------------------------------------

namespace {

// The declared rules, or one per salient action (on its focal argument).
std::vector<OptionRule> option_rules(const PackSpec& spec) {
  if (!spec.options.empty()) return spec.options;
  std::vector<OptionRule> out;
  for (const auto& r : spec.language.salient_actions) out.push_back({r.action, r.focal_arg, "", ""});
  return out;
}

}  // namespace

std::optional<std::string> Pack::option_of(const pddl::Task& task, pddl::ActionId a, const std::string& tag) const {
  const auto& ga = task.action(a);
  if (ga.args.empty() || task.object_name(ga.args[0]) != spec_.roles.assistant) return std::nullopt;
  const std::string& name = task.domain().actions[ga.schema].name;
  for (const auto& r : option_rules(spec_)) {
    if (r.action != name || (!r.tag.empty() && r.tag != tag)) continue;
    if (r.object_arg > static_cast<int>(ga.args.size())) continue;
    const pddl::ObjectId o = ga.args[r.object_arg - 1];
    if (!r.object_type.empty() && !task.object_is_a(o, r.object_type)) continue;
    return task.object_name(o);
  }
  return std::nullopt;
}

std::vector<std::string> Pack::options_taken(const pddl::PlanFile& completed, const std::string& tag,
                                             const pddl::Task* task) const {
  std::vector<std::string> out;
  const auto rules = option_rules(spec_);
  for (const auto& line : completed.actions) {
    auto e = pddl::read_one_sexpr(line.text, line.loc.file);
    if (!e.is_list || e.items.size() < 2 || e.items[1].atom != spec_.roles.assistant) continue;
    for (const auto& r : rules) {
      if (r.action != e.head() || (!r.tag.empty() && r.tag != tag)) continue;
      if (r.object_arg >= static_cast<int>(e.items.size())) continue;
      const std::string& o = e.items[static_cast<size_t>(r.object_arg)].atom;
      if (!r.object_type.empty() && task) {
        auto id = task->find_object(o);
        if (!id || !task->object_is_a(*id, r.object_type)) continue;
      }
      if (std::find(out.begin(), out.end(), o) == out.end()) out.push_back(o);
      break;
    }
  }
  return out;
}

bool Pack::is_option_object(const pddl::Task& task, const std::string& object, const std::string& tag) const {
  auto id = task.find_object(object);
  if (!id) return false;
  for (const auto& r : option_rules(spec_)) {
    if (!r.tag.empty() && r.tag != tag) continue;
    std::string type = r.object_type;
    if (type.empty()) {
      const int schema = task.domain().find_action(r.action);
      if (schema < 0) continue;
      const auto& params = task.domain().actions[static_cast<size_t>(schema)].param_types;
      if (r.object_arg > static_cast<int>(params.size())) continue;
      type = task.domain().types[static_cast<size_t>(params[static_cast<size_t>(r.object_arg - 1)])].name;
    }
    if (task.object_is_a(*id, type)) return true;
  }
  return false;
}

// ---- showing states ---------------------------------------------------------------

std::string Pack::describe_state(const pddl::Task& task, const pddl::State& s) const { return task.state_str(s); }

std::string Pack::object_list(const pddl::Task& task) const {
  const auto qualifier = qualifier_of(task);
  std::string out;
  for (pddl::ObjectId o = 0; o < task.num_objects(); ++o) {
    const std::string& name = task.object_name(o);
    if (name == spec_.roles.principal || name == spec_.roles.assistant) continue;
    out += (out.empty() ? "" : ", ") + name;
    std::string values;
    for (const auto& q : qualifier(name))
      if (q.args.size() == 2) values += (values.empty() ? "" : ", ") + (q.args[0] == name ? q.args[1] : q.args[0]);
    if (!values.empty()) out += " (" + values + ")";
  }
  return out;
}

std::optional<StripsExport> Pack::export_strips(const pddl::Task& task, const pddl::State& start,
                                                const std::string& goal, const model::CostProfile& costs) const {
  return export_grounded_strips(task, start, goal, costs);
}

std::optional<int> Pack::min_principal_actions(const pddl::Task&, const pddl::State&, const std::string&) const {
  return std::nullopt;
}

std::optional<GeneratedProblem> Pack::generate_problem(const GenerateParams&, util::Rng&) const {
  throw InputError("pack " + spec_.name + " cannot generate problems (only packs with generator code can: "
                   "doors-keys-gems)");
}

// ---- checking a spec against a domain ------------------------------------------------

void check_pack_against(const PackSpec& spec, const pddl::Domain& d) {
  const SourceLoc loc{spec.source.empty() ? "pack " + spec.name : spec.source, 0, 0};
  auto fail = [&](const std::string& field, const std::string& why) { throw InputError(loc, field + ": " + why); };
  if (spec.name != d.name)
    fail("domain", "\"" + spec.name + "\" differs from the PDDL domain's name \"" + d.name + "\" (" + d.file + ")");
  auto action = [&](const std::string& field, const std::string& name) {
    const int a = d.find_action(name);
    if (a < 0) fail(field, "the domain has no action '" + name + "'");
    return &d.actions[static_cast<size_t>(a)];
  };
  auto arity_ok = [&](const std::string& field, const pddl::ActionSchema* a, int pos) {
    if (pos < 1 || pos > static_cast<int>(a->param_types.size()))
      fail(field, "action '" + a->name + "' has " + std::to_string(a->param_types.size()) + " parameters, not " +
                      std::to_string(pos));
  };
  auto type = [&](const std::string& field, const std::string& name) {
    if (!d.find_type(name)) fail(field, "the domain has no type '" + name + "'");
  };
  // The turns and freezing clips adds (and the no-op, when it compiles the turns).
  const TaskTransform added = plan_task_transform(spec, d);
  if (!added.add_noop) {
    // The no-op is one agent's turn without a move, (wait ?a): the policies
    // and cost profiles read it as a one-argument action of that agent.
    const auto* noop = action("roles.noop_action", spec.roles.noop_action);
    if (noop->param_types.size() != 1)
      fail("roles.noop_action", "action '" + noop->name + "' has " + std::to_string(noop->param_types.size()) +
                                    " parameters; the no-op takes exactly one, the agent that waits (as (" +
                                    noop->name + " ?a - agent))");
  }
  for (size_t i = 0; i < spec.grounding.schema_order.size(); ++i)
    action("grounding.schema_order[" + std::to_string(i) + "]", spec.grounding.schema_order[i]);
  if (spec.goals.source == GoalSource::Objects) type("goals.object_type", spec.goals.object_type);
  for (size_t i = 0; i < spec.language.salient_actions.size(); ++i) {
    const auto& r = spec.language.salient_actions[i];
    const std::string f = "language.salient_actions[" + std::to_string(i) + "]";
    auto* a = action(f + ".action", r.action);
    arity_ok(f + ".agent_arg", a, r.agent_arg);
    arity_ok(f + ".focal_arg", a, r.focal_arg);
  }
  for (const auto& [name, atoms] : spec.language.goal_atoms) {
    const auto* a = action("language.goal_atoms." + name, name);
    // Every $N must name one of the action's parameters (else `listen` fails
    // on the first command of that action).
    for (size_t i = 0; i < atoms.size(); ++i) {
      const std::string f = "language.goal_atoms." + name + "[" + std::to_string(i) + "]";
      const std::string& t = atoms[i];
      for (size_t at = t.find('$'); at != std::string::npos; at = t.find('$', at + 1)) {
        size_t end = at + 1;
        while (end < t.size() && t[end] != ' ' && t[end] != '\t' && t[end] != ')' && t[end] != '(') ++end;
        const std::string ref = t.substr(at, end - at);
        const std::string digits = ref.substr(1);
        if (digits.empty() || digits.size() > 4 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
          fail(f, "'" + ref + "' in \"" + t + "\" is not an argument reference ($1, $2, ...)");
        const int pos = std::stoi(digits);
        if (pos < 1 || pos > static_cast<int>(a->param_types.size()))
          fail(f, "'" + ref + "' in \"" + t + "\" names parameter " + std::to_string(pos) + ", but action '" + name +
                      "' has " + std::to_string(a->param_types.size()));
      }
      // Expanded as the listener will expand it (else a malformed template,
      // "(not (holding $1 $2)) extra)", fails there as an internal error).
      commands::LanguageConfig one = spec.language;
      one.goal_atoms = {{name, {t}}};
      commands::Command probe;
      probe.actions.push_back({name, {}});
      for (size_t k = 0; k < a->param_types.size(); ++k) probe.actions[0].args.push_back("x" + std::to_string(k + 1));
      try {
        (void)probe.to_goal_formula(one);
      } catch (const std::invalid_argument& e) {
        fail(f, "\"" + t + "\" is not an atom template (" + e.what() + ")");
      }
    }
  }
  if (!spec.language.salient_actions.empty()) {
    const auto names = spec.language.qualifiers();
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string field = i == 0 ? "language.qualifier.predicate" : "language.qualifier.more[" + std::to_string(i - 1) + "]";
      auto q = d.find_predicate(names[i]);
      if (!q) fail(field, "the domain has no predicate '" + names[i] + "'");
      if (d.predicates[*q].arg_types.size() != 2)
        fail(field, "'" + names[i] + "' must take 2 arguments (object, value)");
    }
  }
  for (size_t i = 0; i < spec.options.size(); ++i) {
    const std::string f = "assistance_options[" + std::to_string(i) + "]";
    auto* a = action(f + ".action", spec.options[i].action);
    arity_ok(f + ".object_arg", a, spec.options[i].object_arg);
    if (!spec.options[i].object_type.empty()) type(f + ".object_type", spec.options[i].object_type);
  }
  if (!spec.inference.rollout.speaker_flag.empty() && !d.find_predicate(spec.inference.rollout.speaker_flag))
    fail("inference.rollout.speaker_flag", "the domain has no predicate '" + spec.inference.rollout.speaker_flag + "'");
  for (size_t i = 0; i < spec.literal.variable_types.size(); ++i)
    type("literal_listener.variable_types[" + std::to_string(i) + "]", spec.literal.variable_types[i]);
  for (const auto& r : spec.cost_profiles)
    for (const auto& p : r.profiles)
      for (const auto& [key, cost] : p.costs)
        action("cost_profiles: profile " + p.name + ": costs." + key.first, key.second);
  if (spec.scene == SceneKind::Grid) {
    // The grid scene draws Doors-Keys-Gems maps from these fluents.
    for (const auto& [name, arity] : {std::pair<const char*, size_t>{"walls", 0}, {"xloc", 1}, {"yloc", 1}}) {
      const auto f = d.find_function(name);
      if (!f || d.functions[static_cast<size_t>(*f)].arg_types.size() != arity)
        fail("scene", std::string("\"grid\" draws Doors-Keys-Gems maps, which need the domain's functions (walls), "
                                  "(xloc ?o) and (yloc ?o); this domain has no (") + name +
                          (arity ? " ?o" : "") + "): use \"text\"");
    }
  }
  if (!spec.fewshot.file.empty()) {
    fs::path file(spec.fewshot.file);
    if (file.is_relative() && !spec.source.empty()) file = fs::path(spec.source).parent_path() / file;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
      fail("fewshot.file", "no file " + file.string() +
                               (fs::path(spec.fewshot.file).is_relative() ? " (read from the pack file's folder)" : ""));
  }
}

// ---- goal atoms from effects ------------------------------------------------------------

namespace {

// The unconditional add/delete effects of an effect tree (not under when/forall).
void plain_effects(const pddl::Effect& e, std::vector<const pddl::Effect*>& out) {
  switch (e.kind) {
    case pddl::Effect::Kind::And:
      for (const auto& k : e.kids) plain_effects(k, out);
      return;
    case pddl::Effect::Kind::Add:
    case pddl::Effect::Kind::Del: out.push_back(&e); return;
    default: return;
  }
}

}  // namespace

std::vector<std::string> goal_atoms_from_effects(const pddl::Domain& d, const commands::SalientActionRule& rule,
                                                 const std::string& turn_predicate) {
  std::vector<std::string> out;
  const int a = d.find_action(rule.action);
  if (a < 0) return out;
  const pddl::ActionSchema& schema = d.actions[static_cast<size_t>(a)];
  const int focal = rule.focal_arg - 1;
  if (focal < 0 || focal >= static_cast<int>(schema.param_types.size())) return out;
  std::vector<const pddl::Effect*> effects;
  plain_effects(schema.effect, effects);
  for (const pddl::Effect* e : effects) {
    const std::string& pred = d.predicates[static_cast<size_t>(e->pred)].name;
    if (pred == turn_predicate || pred == "frozen") continue;  // bookkeeping of turns and simulations
    bool names_focal = false, printable = true;
    std::string atom = "(" + pred;
    for (const pddl::TermRef& t : e->args) {
      if (t.is_var && t.index < static_cast<int>(schema.param_types.size())) {
        names_focal = names_focal || t.index == focal;
        atom += " $" + std::to_string(t.index + 1);
      } else if (!t.is_var && t.index >= 0 && t.index < static_cast<int>(d.constants.size())) {
        atom += " " + d.constants[static_cast<size_t>(t.index)].name;
      } else {
        printable = false;
      }
    }
    atom += ")";
    if (!names_focal || !printable) continue;
    if (e->kind == pddl::Effect::Kind::Del) atom = "(not " + atom + ")";
    if (std::find(out.begin(), out.end(), atom) == out.end()) out.push_back(atom);
  }
  return out;
}

void derive_goal_atoms(PackSpec& spec, const pddl::Domain& domain) {
  for (const auto& rule : spec.language.salient_actions) {
    if (spec.language.goal_atoms.count(rule.action)) continue;
    auto atoms = goal_atoms_from_effects(domain, rule, spec.roles.turn_predicate);
    if (atoms.empty()) continue;
    spec.language.goal_atoms[rule.action] = std::move(atoms);
    spec.derived_goal_atoms.push_back(rule.action);
  }
  // A salient action the listener may hear needs its goal atoms (else the
  // first command naming it fails as an internal error).
  for (size_t i = 0; i < spec.language.salient_actions.size(); ++i) {
    const auto& r = spec.language.salient_actions[i];
    if (!spec.language.goal_atoms.count(r.action))
      throw InputError(spec.source + ": language.salient_actions[" + std::to_string(i) + "]: action '" + r.action +
                       "' has no language.goal_atoms, and none can be derived: no effect of it names its focal_arg " +
                       std::to_string(r.focal_arg));
  }
}

// ---- where objects are ---------------------------------------------------------------------

namespace {

// Predicates some action's effect adds or deletes (under when/forall too).
void changed_predicates(const pddl::Effect& e, std::set<pddl::PredId>& out) {
  if (e.kind == pddl::Effect::Kind::Add || e.kind == pddl::Effect::Kind::Del) out.insert(e.pred);
  for (const auto& k : e.kids) changed_predicates(k, out);
}

}  // namespace

std::vector<std::string> location_predicates(const pddl::Domain& d, const std::string& agent_type) {
  std::vector<std::string> out;
  const auto agent = d.find_type(agent_type);
  if (!agent) return out;
  std::set<pddl::PredId> changed;
  for (const auto& a : d.actions) changed_predicates(a.effect, changed);
  auto related = [&](pddl::TypeId a, pddl::TypeId b) { return d.is_subtype(a, b) || d.is_subtype(b, a); };
  auto agentish = [&](pddl::TypeId t) { return related(t, *agent) && t != 0; };
  std::vector<pddl::TypeId> places;
  for (pddl::PredId p : changed) {
    const auto& types = d.predicates[static_cast<size_t>(p)].arg_types;
    if (types.size() == 2 && agentish(types[0]) && !agentish(types[1]) && types[1] != 0) places.push_back(types[1]);
  }
  for (pddl::PredId p : changed) {
    const auto& types = d.predicates[static_cast<size_t>(p)].arg_types;
    // The first argument must be able to hold a thing that is not an agent:
    // (in ?i - item ?p - place), or one predicate for both, (at ?x - locatable
    // ?p - place) with agent and item under locatable; (at ?a - agent ...) is
    // only where agents are.
    if (types.size() != 2 || d.is_subtype(types[0], *agent) || types[0] == 0) continue;
    if (std::any_of(places.begin(), places.end(), [&](pddl::TypeId t) { return related(types[1], t); }))
      out.push_back(d.predicates[static_cast<size_t>(p)].name);
  }
  // Where an agent leaves what it held, when that is no place anyone stands
  // (a shelf, a bed, a cabinet): an action that deletes (Q ?agent ?x) and
  // adds (P ?x ?y), neither ?x nor ?y an agent nor of related types (a
  // block on a block is a thing, not a place).
  for (const pddl::ActionSchema& a : d.actions) {
    std::vector<const pddl::Effect*> adds, dels;
    std::vector<const pddl::Effect*> stack{&a.effect};
    while (!stack.empty()) {
      const pddl::Effect* e = stack.back();
      stack.pop_back();
      if (e->kind == pddl::Effect::Kind::Add) adds.push_back(e);
      if (e->kind == pddl::Effect::Kind::Del) dels.push_back(e);
      if (e->kind == pddl::Effect::Kind::And)
        for (const auto& k : e->kids) stack.push_back(&k);
    }
    auto param_type = [&](const pddl::TermRef& arg) {
      return arg.index >= 0 && static_cast<size_t>(arg.index) < a.param_types.size()
                 ? a.param_types[static_cast<size_t>(arg.index)]
                 : pddl::TypeId{0};
    };
    for (const pddl::Effect* add : adds) {
      if (add->args.size() != 2 || !add->args[0].is_var || !add->args[1].is_var) continue;
      const pddl::TypeId x = param_type(add->args[0]), y = param_type(add->args[1]);
      if (agentish(x) || agentish(y) || related(x, y) || x == 0 || y == 0) continue;
      const bool from_hands = std::any_of(dels.begin(), dels.end(), [&](const pddl::Effect* del) {
        return del->args.size() == 2 && del->args[0].is_var && del->args[1].is_var &&
               agentish(param_type(del->args[0])) && del->args[1].index == add->args[0].index;
      });
      const std::string& name = d.predicates[static_cast<size_t>(add->pred)].name;
      if (from_hands && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    }
  }
  return out;
}

void derive_location_predicates(PackSpec& spec, const pddl::Domain& domain) {
  if (spec.language.locations_auto) spec.language.location_predicates = location_predicates(domain, spec.roles.agent_type);
  derive_destinations(spec, domain);
}

namespace {
// The parameter slot an effect adds (L focal slot) for, for a location predicate L; -1: none.
int added_place_slot(const pddl::Effect& e, const pddl::Domain& d, const commands::LanguageConfig& language,
                     int focal_slot) {
  if (e.kind == pddl::Effect::Kind::Add && e.args.size() == 2 && e.args[0].is_var && e.args[1].is_var &&
      e.args[0].index == focal_slot && language.is_location(d.predicates[static_cast<size_t>(e.pred)].name))
    return e.args[1].index;
  if (e.kind == pddl::Effect::Kind::And)
    for (const pddl::Effect& k : e.kids)
      if (const int slot = added_place_slot(k, d, language, focal_slot); slot >= 0) return slot;
  return -1;
}
}  // namespace

void derive_destinations(PackSpec& spec, const pddl::Domain& domain) {
  // The place (second) and the located (first) argument of each location predicate.
  std::vector<pddl::TypeId> place_types, located_types;
  for (const std::string& name : spec.language.location_predicates) {
    const auto p = domain.find_predicate(name);
    if (!p) continue;
    const auto& types = domain.predicates[static_cast<size_t>(*p)].arg_types;
    if (types.size() != 2) continue;
    place_types.push_back(types[1]);
    located_types.push_back(types[0]);
  }
  // A place that is itself put somewhere, as a block on a block, is a thing
  // like any other and stays lifted.
  const auto is_place = [&](pddl::TypeId t) {
    const auto under = [&](pddl::TypeId of) { return of != 0 && domain.is_subtype(t, of); };
    return std::any_of(place_types.begin(), place_types.end(), under) &&
           std::none_of(located_types.begin(), located_types.end(), under);
  };
  for (commands::SalientActionRule& r : spec.language.salient_actions) {
    r.destination_arg = 0;
    r.focal_is_place = false;
    const auto schema = std::find_if(domain.actions.begin(), domain.actions.end(),
                                     [&](const pddl::ActionSchema& a) { return a.name == r.action; });
    if (schema == domain.actions.end()) continue;
    const int params = static_cast<int>(schema->param_types.size());
    if (r.focal_arg < 1 || r.focal_arg > params) continue;
    const pddl::TypeId focal_type = schema->param_types[static_cast<size_t>(r.focal_arg - 1)];
    r.focal_is_place = is_place(focal_type);
    if (!spec.language.destinations) continue;
    const int slot = added_place_slot(schema->effect, domain, spec.language, r.focal_arg - 1);
    if (slot >= 0 && slot < params && slot + 1 != r.agent_arg && slot + 1 != r.focal_arg) r.destination_arg = slot + 1;
  }
}

// ---- finding a pack -----------------------------------------------------------------

namespace {
// A parent type nothing declares is a slip (`car - vehical`) unless it is the
// agents' type, which docs/domains.md lets a domain leave implicit.
void check_implicit_types(const PackSpec& spec, const pddl::Domain& d) {
  for (const auto& [name, loc] : d.implicit_parents) {
    if (name == spec.roles.agent_type) continue;
    throw InputError(loc, "type '" + name + "' is named as a parent but never declared; declare it in :types ('" +
                              name + " - object'), or correct the name (only the agents' type '" +
                              spec.roles.agent_type + "', roles.agent_type, may be left undeclared)");
  }
}
}  // namespace

std::optional<PackSpec> declared_pack_spec(const pddl::Domain& domain, const std::string& dir) {
  if (!dir.empty() && fs::exists(fs::path(dir) / "pack.json")) return load_pack_spec((fs::path(dir) / "pack.json").string());
  std::error_code ec;
  const fs::path shared = fs::path(util::data_dir()) / "domains" / domain.name / "pack.json";
  if (fs::exists(shared, ec)) return load_pack_spec(shared.string());
  return builtin_pack_spec(domain.name);
}

PackSpec generic_pack_spec(const pddl::Domain& domain) {
  PackSpec s;
  s.name = domain.name;
  s.generic = true;
  s.grounding.keep_dynamic = {"frozen", "nograb", "noput"};
  s.language.domain = s.name;
  s.language.salient_actions.clear();
  s.fewshot.domain = s.name;
  // Nothing to check against the domain: `clips plan` works on any domain.
  check_implicit_types(s, domain);
  derive_goal_atoms(s, domain);
  derive_location_predicates(s, domain);
  return s;
}

PackSpec pack_spec_for_domain(PackSpec spec, const pddl::Domain& domain) {
  check_implicit_types(spec, domain);
  check_pack_against(spec, domain);
  spec.transform = plan_task_transform(spec, domain);
  derive_goal_atoms(spec, domain);
  derive_location_predicates(spec, domain);
  return spec;
}

std::string domain_misfit(const pddl::Domain& d, const DomainNeeds& needs) {
  for (const char* t : needs.types)
    if (!d.find_type(t)) return std::string("no type '") + t + "'";
  for (const auto& [name, arity] : needs.predicates) {
    const auto p = d.find_predicate(name);
    if (!p || d.predicates[static_cast<size_t>(*p)].arg_types.size() != arity)
      return "no predicate '" + std::string(name) + "' of " + std::to_string(arity) + " arguments";
  }
  for (const auto& [name, arity] : needs.functions) {
    const auto f = d.find_function(name);
    if (!f || d.functions[static_cast<size_t>(*f)].arg_types.size() != arity)
      return "no function (" + std::string(name) + (arity ? " ?o" : "") + ")";
  }
  return "";
}

}  // namespace clips::domains
