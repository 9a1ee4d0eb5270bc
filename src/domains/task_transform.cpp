// Task transformations (task_transform.hpp): freezing and compiled turns,
// added to the parsed domain and problems before grounding.
#include "domains/task_transform.hpp"

#include <algorithm>

#include "util/error.hpp"

namespace clips::domains {

namespace {

using pddl::Condition;
using pddl::Effect;
using pddl::PredId;
using pddl::TermRef;
using pddl::TypeId;

constexpr const char* kFrozen = "frozen";
constexpr const char* kNextTurn = "next-turn";

SourceLoc pack_loc(const PackSpec& spec) { return SourceLoc{spec.source.empty() ? "pack " + spec.name : spec.source, 0, 0}; }

[[noreturn]] void fail(const PackSpec& spec, const std::string& field, const std::string& why) {
  throw InputError(pack_loc(spec), field + ": " + why);
}

// What clips would add, for error messages ("(frozen ?a)", "the turns").
std::string what_is_added(const TaskTransform& t, const Roles& r) {
  std::string out;
  if (t.compile_turns) out = "the turns (" + r.turn_predicate + ", next-turn)";
  if (t.add_frozen) out += std::string(out.empty() ? "" : " and ") + "(frozen ?a)";
  return out;
}

TermRef var(int slot) { return TermRef{true, slot}; }

Condition atom(PredId p, std::vector<TermRef> args, const SourceLoc& loc) {
  Condition c;
  c.kind = Condition::Kind::Atom;
  c.pred = p;
  c.args = std::move(args);
  c.loc = loc;
  return c;
}

Effect literal(Effect::Kind kind, PredId p, std::vector<TermRef> args, const SourceLoc& loc) {
  Effect e;
  e.kind = kind;
  e.pred = p;
  e.args = std::move(args);
  e.loc = loc;
  return e;
}

// Inserts `c` into the top-level conjunction of `pre` at `pos` (clamped).
void add_conjunct(std::optional<Condition>& pre, Condition c, size_t pos) {
  if (!pre) {
    pre = std::move(c);
    return;
  }
  if (pre->kind != Condition::Kind::And) {
    Condition both;
    both.kind = Condition::Kind::And;
    both.loc = pre->loc;
    both.kids.push_back(std::move(*pre));
    pre = std::move(both);
  }
  pre->kids.insert(pre->kids.begin() + static_cast<std::ptrdiff_t>(std::min(pos, pre->kids.size())), std::move(c));
}

void add_effect(Effect& eff, Effect e) {
  if (eff.kind != Effect::Kind::And) {
    Effect both;
    both.kind = Effect::Kind::And;
    both.loc = eff.loc;
    both.kids.push_back(std::move(eff));
    eff = std::move(both);
  }
  eff.kids.push_back(std::move(e));
}

PredId add_predicate(pddl::Domain& d, const std::string& name, std::vector<TypeId> types) {
  pddl::PredicateDef p;
  p.name = name;
  p.arg_types = std::move(types);
  p.loc = SourceLoc{d.file, 0, 0};
  d.predicates.push_back(std::move(p));
  return static_cast<PredId>(d.predicates.size() - 1);
}

// Whether the precondition starts with (<turn> ?a), ?a the first parameter.
bool starts_with_turn(const pddl::ActionSchema& a, std::optional<PredId> turn) {
  if (!turn || !a.precondition) return false;
  const Condition* first = &*a.precondition;
  if (first->kind == Condition::Kind::And) {
    if (first->kids.empty()) return false;
    first = &first->kids.front();
  }
  return first->kind == Condition::Kind::Atom && first->pred == *turn && first->args.size() == 1 &&
         first->args[0].is_var && first->args[0].index == 0;
}

}  // namespace

TaskTransform plan_task_transform(const PackSpec& spec, const pddl::Domain& d) {
  TaskTransform t;
  if (spec.generic) return t;
  const Roles& r = spec.roles;
  const bool has_turn = d.find_predicate(r.turn_predicate).has_value();
  const TurnMode mode = r.turns == TurnMode::Auto ? (has_turn ? TurnMode::Domain : TurnMode::Alternate) : r.turns;
  if (mode == TurnMode::Domain && !has_turn)
    fail(spec, "roles.turns", "\"domain\" says the domain writes its own turn idiom, but it declares no turn predicate '" +
                                  r.turn_predicate + "' (roles.turn_predicate); leave roles.turns out (or \"alternate\") "
                                  "and clips adds the turns");
  if (mode != TurnMode::Domain && has_turn)
    fail(spec, "roles.turns", "the domain declares the turn predicate '" + r.turn_predicate +
                                  "' itself (its own turn idiom), so clips cannot compile the turns in: use \"domain\", or "
                                  "name an unused predicate in roles.turn_predicate");
  t.compile_turns = mode != TurnMode::Domain;
  t.add_frozen = !d.find_predicate(kFrozen);
  const int noop = d.find_action(r.noop_action);
  t.add_noop = t.compile_turns && noop < 0;
  if (t.empty()) return t;

  const std::string adds = what_is_added(t, r);
  const auto agent = d.find_type(r.agent_type);
  if (!agent)
    fail(spec, "roles.agent_type", "the domain has no type '" + r.agent_type + "', the agents' type clips needs to add " +
                                       adds + "; declare it (e.g. (:types cook helper - " + r.agent_type +
                                       ")) or name the agents' type here");
  t.agent_type = r.agent_type;
  if (t.compile_turns) {
    if (d.find_predicate(kNextTurn))
      fail(spec, "roles.turns", "the domain declares 'next-turn' but not the turn predicate '" + r.turn_predicate +
                                    "': write the whole turn idiom (and \"turns\": \"domain\") or neither");
    t.turn_order = mode == TurnMode::Alternate ? std::vector<std::string>{r.principal, r.assistant} : r.turn_order;
  }
  // The acting agent of every action is its first parameter.
  for (const auto& a : d.actions) {
    const std::string why = "clips takes an action's first parameter as the acting agent, to add " + adds;
    if (a.param_types.empty())
      throw InputError(a.loc, "action '" + a.name + "' has no parameters, so no acting agent: " + why +
                                  "; give it the agent as its first parameter (?a - " + r.agent_type + ")");
    if (d.is_subtype(a.param_types[0], *agent)) continue;
    std::string hint;
    for (size_t i = 1; i < a.param_types.size() && hint.empty(); ++i)
      if (d.is_subtype(a.param_types[i], *agent)) hint = " (move ?" + a.param_names[i] + " to the front)";
    throw InputError(a.loc, "action '" + a.name + "': its first parameter ?" + a.param_names[0] + " is of type '" +
                                d.types[static_cast<size_t>(a.param_types[0])].name + "', not the agents' type '" +
                                r.agent_type + "' (roles.agent_type): " + why + hint);
  }
  if (noop >= 0 && d.actions[static_cast<size_t>(noop)].param_types.size() != 1)
    throw InputError(d.actions[static_cast<size_t>(noop)].loc,
                     "the no-op action '" + r.noop_action + "' (roles.noop_action) must take one parameter, the agent");
  return t;
}

bool is_prepared(const PackSpec& spec, const pddl::Domain& d) {
  const TaskTransform& t = spec.transform;
  return (!t.compile_turns || d.find_predicate(spec.roles.turn_predicate)) && (!t.add_frozen || d.find_predicate(kFrozen));
}

std::shared_ptr<const pddl::Domain> prepare_domain(const PackSpec& spec, std::shared_ptr<const pddl::Domain> domain) {
  const TaskTransform& t = spec.transform;
  if (t.empty() || is_prepared(spec, *domain)) return domain;
  const Roles& r = spec.roles;
  auto d = std::make_shared<pddl::Domain>(*domain);
  const auto agent_type = d->find_type(t.agent_type);
  if (!agent_type) throw InputError("pack " + spec.name + ": the domain has no type '" + t.agent_type + "' (roles.agent_type)");
  const TypeId agent = *agent_type;
  if (t.compile_turns) {
    const PredId turn = add_predicate(*d, r.turn_predicate, {agent});
    const PredId next = add_predicate(*d, kNextTurn, {agent, agent});
    if (t.add_noop) {
      pddl::ActionSchema noop;
      noop.name = r.noop_action;
      noop.param_names = {"a"};
      noop.param_types = {agent};
      noop.num_vars = 1;
      noop.loc = SourceLoc{d->file, 0, 0};
      d->actions.push_back(std::move(noop));
    }
    for (auto& a : d->actions) {
      // (<turn> ?a) first: the grounder keys an action's applicability on the
      // first positive atom of its precondition, so each agent's actions are
      // looked at only on its turn.
      add_conjunct(a.precondition, atom(turn, {var(0)}, a.loc), 0);
      // (not (<turn> ?a)) (forall (?b - agent) (when (next-turn ?a ?b) (<turn> ?b)))
      const int b = a.num_vars++;
      Effect when;
      when.kind = Effect::Kind::When;
      when.cond = atom(next, {var(0), var(b)}, a.loc);
      when.kids.push_back(literal(Effect::Kind::Add, turn, {var(b)}, a.loc));
      when.loc = a.loc;
      Effect forall;
      forall.kind = Effect::Kind::Forall;
      forall.var_types = {agent};
      forall.first_var = b;
      forall.kids.push_back(std::move(when));
      forall.loc = a.loc;
      add_effect(a.effect, literal(Effect::Kind::Del, turn, {var(0)}, a.loc));
      add_effect(a.effect, std::move(forall));
    }
  }
  if (t.add_frozen) {
    const PredId frozen = add_predicate(*d, kFrozen, {agent});
    const auto turn = d->find_predicate(r.turn_predicate);
    for (auto& a : d->actions) {
      if (a.name == r.noop_action) continue;
      Condition c;
      c.kind = Condition::Kind::Not;
      c.kids.push_back(atom(frozen, {var(0)}, a.loc));
      c.loc = a.loc;
      // After the turn atom when the precondition starts with it, as the
      // paper domains write it: (and (active ?a) (not (frozen ?a)) ...).
      add_conjunct(a.precondition, std::move(c), starts_with_turn(a, turn) ? 1 : 0);
    }
  }
  return d;
}

void prepare_problem(const PackSpec& spec, const pddl::Domain& d, pddl::Problem& problem) {
  if (spec.generic) return;
  const Roles& r = spec.roles;
  const SourceLoc loc{problem.file, 0, 0};
  const std::string pack = " (pack " + (spec.source.empty() ? spec.name : spec.source) + ")";
  for (const auto& [field, name] : {std::pair<const char*, const std::string*>{"roles.principal", &r.principal},
                                    {"roles.assistant", &r.assistant}})
  {
    const auto o = problem.find_object(*name);
    if (!o)
      throw InputError(loc, std::string(field) + " names '" + *name + "', which is not an object of this problem" + pack);
    // An agent is the first argument of the actions it takes; an object no
    // action can take as its first argument (a place, an item) never acts.
    const TypeId type = problem.objects[static_cast<size_t>(*o)].type;
    const bool acts = std::any_of(d.actions.begin(), d.actions.end(), [&](const pddl::ActionSchema& a) {
      return !a.param_types.empty() && d.is_subtype(type, a.param_types[0]);
    });
    if (!acts)
      throw InputError(loc, std::string(field) + " names '" + *name + "', of type '" +
                                d.types[static_cast<size_t>(type)].name +
                                "', which no action takes as its agent (first parameter): the roles must be agents" +
                                pack);
  }
  const TaskTransform& t = spec.transform;
  if (!t.compile_turns) return;
  const auto turn = d.find_predicate(r.turn_predicate), next = d.find_predicate(kNextTurn);
  const auto agent = d.find_type(t.agent_type);
  if (!turn || !next || !agent)
    throw InputError(loc, "the domain was not prepared for pack " + spec.name + " (no compiled turn predicate)");
  for (const auto& a : problem.init_atoms)
    if (a.pred == *turn || a.pred == *next)
      throw InputError(a.loc, "the problem states a '" + d.predicates[static_cast<size_t>(a.pred)].name +
                                  "' fact, but clips adds the turns itself (roles.turns): leave the turn facts out" + pack);
  std::vector<pddl::ObjectId> order;
  for (size_t i = 0; i < t.turn_order.size(); ++i) {
    const std::string& name = t.turn_order[i];
    const std::string field = r.turns == TurnMode::Order ? "roles.turns[" + std::to_string(i) + "]"
                              : i == 0                   ? "roles.principal"
                                                         : "roles.assistant";
    const auto o = problem.find_object(name);
    if (!o) throw InputError(loc, field + " names '" + name + "', which is not an object of this problem" + pack);
    if (!d.is_subtype(problem.objects[static_cast<size_t>(*o)].type, *agent))
      throw InputError(loc, field + " names '" + name + "', which is not of the agents' type '" + t.agent_type +
                                "' (roles.agent_type)" + pack);
    order.push_back(*o);
  }
  problem.init_atoms.push_back({*turn, {order.front()}, loc});
  for (size_t i = 0; i < order.size(); ++i) problem.init_atoms.push_back({*next, {order[i], order[(i + 1) % order.size()]}, loc});
}

}  // namespace clips::domains
