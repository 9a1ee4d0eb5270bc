#include "domains/dkg/dkg_strips.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "domains/dkg/dkg_world.hpp"
#include "pddl/sexpr.hpp"

namespace clips::domains::dkg {

using pddl::ObjectId;

namespace {

std::string cell_name(int x, int y) { return fmt::format("c_{}_{}", x, y); }

// The four moves of the original domain with their direction and the name of
// the static fact that encodes "?to is the neighbour of ?from that way".
struct Move {
  const char* action;  // original action name
  const char* fact;    // exported static predicate
  int dx, dy;
};
constexpr Move kMoves[] = {
    {"up", "up-of", 0, -1}, {"down", "down-of", 0, 1}, {"left", "left-of", -1, 0}, {"right", "right-of", 1, 0}};

// Collects the (has agent item) atoms of a conjunction; anything else is out
// of scope because the compiled domain only keeps these fluents faithfully.
void collect_has_atoms(const pddl::SExpr& e, std::vector<std::pair<std::string, std::string>>& out,
                       const std::string& whole) {
  auto unsupported = [&] {
    return InputError("export-strips supports goals that are a conjunction of (has <agent> <item>) atoms, got '" +
                      whole + "'");
  };
  if (!e.is_list || e.items.empty()) throw unsupported();
  if (e.head() == "and") {
    for (size_t i = 1; i < e.items.size(); ++i) collect_has_atoms(e.items[i], out, whole);
    return;
  }
  if (e.head() != "has" || e.items.size() != 3 || e.items[1].is_list || e.items[2].is_list) throw unsupported();
  out.emplace_back(e.items[1].atom, e.items[2].atom);
}

// The integer a cost becomes after scaling (integer_cost_scale checked it is one).
long long scaled(double cost, int scale) { return std::llround(cost * scale); }

}  // namespace

StripsExport export_strips(const pddl::Task& task, const pddl::State& start, const std::string& goal,
                           const model::CostProfile& costs) {
  if (costs.default_cost < 0)
    throw InputError("export-strips needs an explicit cost profile (C1..C4 or unit); the mDKG domain has no own costs");
  DkgWorld world(task);
  const auto& dom = task.domain();
  for (const char* p : {"has", "locked", "active", "next-turn", "forbidden", "iscolor"})
    if (!dom.find_predicate(p)) throw InputError(fmt::format("not a Doors-Keys-Gems domain: no predicate '{}'", p));

  const std::vector<ObjectId>& agents = world.agents();
  std::vector<std::string> agent_names;
  for (ObjectId a : agents) {
    const std::string& n = world.name(a);
    // Schema names are "<type>-<agent>[-<agent>]"; a hyphen inside an agent
    // name would make to_original_action ambiguous.
    if (n.find('-') != std::string::npos)
      throw InputError("export-strips needs agent names without '-', got '" + n + "'");
    agent_names.push_back(n);
  }
  std::vector<ObjectId> items = task.objects_of_type("item");
  auto is_agent = [&](const std::string& n) {
    return std::find(agent_names.begin(), agent_names.end(), n) != agent_names.end();
  };

  // ---- goal
  std::vector<std::pair<std::string, std::string>> goal_atoms;
  collect_has_atoms(pddl::read_one_sexpr(goal, "<goal>"), goal_atoms, goal);
  if (goal_atoms.empty()) throw InputError("export-strips needs at least one (has <agent> <item>) goal atom");
  for (auto& [a, i] : goal_atoms) {
    if (!is_agent(a)) throw InputError("goal '" + goal + "': '" + a + "' is not an agent");
    auto io = task.find_object(i);
    if (!io || !task.object_is_a(*io, "item")) throw InputError("goal '" + goal + "': '" + i + "' is not an item");
  }

  // ---- costs: one integer per (agent, action type)
  static const char* kActions[] = {"up", "down", "left", "right", "pickup", "unlock", "handover", "wait"};
  std::vector<double> all_costs;
  for (auto& a : agent_names)
    for (const char* act : kActions) all_costs.push_back(costs.cost(a, act));
  int scale = integer_cost_scale(all_costs);
  auto cost_of = [&](const std::string& agent, const char* act) { return scaled(costs.cost(agent, act), scale); };

  // ---- cells: every free in-grid cell, plus any cell a door, agent or item
  // occupies (a door drawn on a wall is still unlockable from next to it).
  std::set<std::pair<int, int>> cells;  // (y, x) so the listing reads row by row
  for (int y = 1; y <= world.height(); ++y)
    for (int x = 1; x <= world.width(); ++x)
      if (!world.wall(x, y)) cells.insert({y, x});
  const SourceLoc problem{task.problem().file, 0, 0};  // errors below name the problem file
  auto place = [&](ObjectId o) -> std::optional<Cell> {
    Cell c = world.pos(start, o);
    if (!c.on_grid()) return std::nullopt;
    if (c.x > world.width() || c.y > world.height())
      throw InputError(problem, fmt::format("{} is outside the {}x{} grid at ({}, {})", world.name(o),
                                            world.width(), world.height(), c.x, c.y));
    cells.insert({c.y, c.x});
    return c;
  };
  std::map<ObjectId, Cell> door_cell, agent_cell, item_cell;
  for (ObjectId d : world.doors()) {
    auto c = place(d);
    if (!c) throw InputError(problem, "door " + world.name(d) + " has no position on the grid");
    door_cell[d] = *c;
  }
  for (ObjectId a : agents) {
    auto c = place(a);
    if (!c) throw InputError(problem, "agent " + world.name(a) + " has no position on the grid");
    agent_cell[a] = *c;
  }
  for (ObjectId i : items)
    if (auto c = place(i)) item_cell[i] = *c;

  // One locked-door flag per cell: with two doors on a cell, unlocking one
  // would wrongly free it, and STRIPS cannot count.
  std::map<std::pair<int, int>, ObjectId> door_on;
  for (auto& [d, c] : door_cell)
    if (!door_on.emplace(std::make_pair(c.x, c.y), d).second)
      throw InputError(fmt::format("two doors on cell ({}, {}) cannot be exported", c.x, c.y));

  std::set<std::string> used_names;
  for (int o = 0; o < task.num_objects(); ++o) used_names.insert(task.object_name(o));
  for (auto& [y, x] : cells)
    if (used_names.count(cell_name(x, y)))
      throw InputError("object name '" + cell_name(x, y) + "' clashes with an exported cell name");

  auto atom_true = [&](const char* pred, const std::vector<std::string>& args) {
    return task.test(start, task.atom(pred, args));
  };

  // ================================================================ domain
  std::string D;
  D += "; Plain-STRIPS compilation of a multi-agent Doors-Keys-Gems problem, written by `clips export-strips`.\n";
  D += fmt::format("; Action costs are the {} profile scaled by {} to integers.\n", costs.name, scale);
  D += "(define (domain doors-keys-gems-strips)\n";
  D += "  (:requirements :strips :typing :action-costs)\n";
  D += "  (:types cell agent door item - object\n          key gem - item)\n";
  D += "  (:constants";
  for (auto& a : agent_names) D += " " + a;
  D += " - agent)\n";
  D += "  (:predicates (at-agent ?a - agent ?c - cell)\n"
       "               (at-item ?i - item ?c - cell)\n"
       "               (has ?a - agent ?i - item)\n"
       "               (may-hold ?a - agent ?i - item)\n"
       "               (unfrozen ?a - agent)\n"
       "               (active ?a - agent)\n"
       "               (locked ?d - door)\n"
       "               (door-at ?d - door ?c - cell)\n"
       "               (open-cell ?c - cell)\n"
       "               (opens ?k - key ?d - door)\n"
       "               (adjacent ?c1 - cell ?c2 - cell)\n"
       "               (up-of ?from - cell ?to - cell)\n"
       "               (down-of ?from - cell ?to - cell)\n"
       "               (left-of ?from - cell ?to - cell)\n"
       "               (right-of ?from - cell ?to - cell))\n";
  D += "  (:functions (total-cost) - number)\n";

  for (size_t ai = 0; ai < agents.size(); ++ai) {
    ObjectId a = agents[ai];
    const std::string& A = agent_names[ai];
    // Turn passing: the acting agent goes inactive and its next-turn
    // successors become active (unless it is its own successor).
    bool self_next = false;
    std::string pass;
    for (size_t bi = 0; bi < agents.size(); ++bi) {
      if (!atom_true("next-turn", {A, agent_names[bi]})) continue;
      if (agents[bi] == a) self_next = true;
      else pass += " (active " + agent_names[bi] + ")";
    }
    if (!self_next) pass += " (not (active " + A + "))";
    auto schema = [&](const std::string& name, const std::string& params, const std::string& pre,
                      const std::string& eff, long long cost) {
      D += fmt::format("\n  (:action {}\n    :parameters ({})\n    :precondition (and (active {}){})\n"
                       "    :effect (and{}{} (increase (total-cost) {})))\n",
                       name, params, A, pre, eff, pass, cost);
    };
    for (const Move& m : kMoves)
      schema(fmt::format("move-{}-{}", m.action, A), "?from - cell ?to - cell",
             fmt::format(" (unfrozen {0}) (at-agent {0} ?from) ({1} ?from ?to) (open-cell ?to)", A, m.fact),
             fmt::format(" (not (at-agent {0} ?from)) (at-agent {0} ?to)", A), cost_of(A, m.action));
    schema("pickup-" + A, "?i - item ?c - cell",
           fmt::format(" (unfrozen {0}) (may-hold {0} ?i) (at-agent {0} ?c) (at-item ?i ?c)", A),
           fmt::format(" (not (at-item ?i ?c)) (has {} ?i)", A), cost_of(A, "pickup"));
    // The key is consumed: it leaves the agent and never returns to the grid.
    schema("unlock-" + A, "?k - key ?d - door ?c - cell ?dc - cell",
           fmt::format(" (unfrozen {0}) (opens ?k ?d) (door-at ?d ?dc) (at-agent {0} ?c) (adjacent ?c ?dc)"
                       " (has {0} ?k) (locked ?d)",
                       A),
           fmt::format(" (not (has {} ?k)) (not (locked ?d)) (open-cell ?dc)", A), cost_of(A, "unlock"));
    // Hand-over and wait do not check `frozen` in the original domain.
    for (size_t bi = 0; bi < agents.size(); ++bi) {
      if (bi == ai) continue;
      const std::string& B = agent_names[bi];
      schema(fmt::format("handover-{}-{}", A, B), "?i - item ?ca - cell ?cb - cell",
             fmt::format(" (has {0} ?i) (may-hold {0} ?i) (may-hold {1} ?i) (at-agent {0} ?ca) (at-agent {1} ?cb)"
                         " (adjacent ?ca ?cb)",
                         A, B),
             fmt::format(" (not (has {} ?i)) (has {} ?i)", A, B), cost_of(A, "handover"));
    }
    schema("wait-" + A, "", "", "", cost_of(A, "wait"));
  }
  D += ")\n";

  // ================================================================ problem
  std::string P;
  P += fmt::format("; Start state of {} as plain STRIPS; goal {}; costs {} x {}.\n", task.problem().name, goal,
                   costs.name, scale);
  P += fmt::format("(define (problem {}-strips) (:domain doors-keys-gems-strips)\n", task.problem().name);
  P += "  (:objects";
  int on_line = 0;
  for (auto& [y, x] : cells) {
    if (on_line++ % 12 == 0) P += "\n    ";
    else P += " ";
    P += cell_name(x, y);
  }
  P += " - cell";
  auto list_objects = [&](const std::vector<ObjectId>& objs, const char* type) {
    if (objs.empty()) return;
    P += "\n   ";
    for (ObjectId o : objs) P += " " + task.object_name(o);
    P += fmt::format(" - {}", type);
  };
  list_objects(world.doors(), "door");
  std::vector<ObjectId> keys, gems, other_items;
  for (ObjectId i : items)
    (task.object_is_a(i, "key") ? keys : task.object_is_a(i, "gem") ? gems : other_items).push_back(i);
  list_objects(keys, "key");
  list_objects(gems, "gem");
  list_objects(other_items, "item");
  P += ")\n  (:init (= (total-cost) 0)\n";

  auto fact = [&](const std::string& f) { P += "    " + f + "\n"; };
  for (size_t ai = 0; ai < agents.size(); ++ai) {
    const std::string& A = agent_names[ai];
    Cell c = agent_cell[agents[ai]];
    fact(fmt::format("(at-agent {} {})", A, cell_name(c.x, c.y)));
    if (world.active(start, agents[ai])) fact(fmt::format("(active {})", A));
    bool frozen = dom.find_predicate("frozen") && atom_true("frozen", {A});
    if (!frozen) fact(fmt::format("(unfrozen {})", A));
  }
  for (ObjectId i : items) {
    auto holder = world.holder(start, i);
    auto it = item_cell.find(i);
    if (holder && it != item_cell.end())
      throw InputError(task.object_name(i) + " is both held and on the grid in the start state");
    if (holder) fact(fmt::format("(has {} {})", world.name(*holder), task.object_name(i)));
    if (it != item_cell.end()) fact(fmt::format("(at-item {} {})", task.object_name(i), cell_name(it->second.x, it->second.y)));
    // A consumed key is neither held nor on the grid: nothing to say.
    for (const auto& A : agent_names)
      if (!atom_true("forbidden", {A, task.object_name(i)})) fact(fmt::format("(may-hold {} {})", A, task.object_name(i)));
  }
  auto colors = task.objects_of_type("color");
  for (ObjectId d : world.doors()) {
    Cell c = door_cell[d];
    fact(fmt::format("(door-at {} {})", task.object_name(d), cell_name(c.x, c.y)));
    if (world.locked(start, d)) fact(fmt::format("(locked {})", task.object_name(d)));
    for (ObjectId k : keys) {
      // Same test as the original unlock: some colour shared by key and door.
      bool match = std::any_of(colors.begin(), colors.end(), [&](ObjectId col) {
        return atom_true("iscolor", {task.object_name(k), task.object_name(col)}) &&
               atom_true("iscolor", {task.object_name(d), task.object_name(col)});
      });
      if (match) fact(fmt::format("(opens {} {})", task.object_name(k), task.object_name(d)));
    }
  }
  for (auto& [y, x] : cells) {
    auto dit = door_on.find({x, y});
    if (dit == door_on.end() || !world.locked(start, dit->second)) fact("(open-cell " + cell_name(x, y) + ")");
  }
  for (auto& [y, x] : cells) {
    for (const Move& m : kMoves) {
      int tx = x + m.dx, ty = y + m.dy;
      if (!cells.count({ty, tx})) continue;
      fact(fmt::format("(adjacent {} {})", cell_name(x, y), cell_name(tx, ty)));
      // Moving needs an in-grid non-wall target; world.wall() says outside is wall.
      if (!world.wall(tx, ty)) fact(fmt::format("({} {} {})", m.fact, cell_name(x, y), cell_name(tx, ty)));
    }
  }
  std::string goal_text = "(and";
  for (auto& [a, i] : goal_atoms) goal_text += fmt::format(" (has {} {})", a, i);
  goal_text += ")";
  P += "  )\n";
  P += "  (:goal " + goal_text + ")\n";
  P += "  (:metric minimize (total-cost)))\n";

  StripsExport out;
  out.domain = std::move(D);
  out.problem = std::move(P);
  out.cost_scale = scale;
  out.goal = goal_text;
  return out;
}

std::string to_original_action(const std::string& exported_action) {
  auto e = pddl::read_one_sexpr(exported_action, "<exported action>");
  auto bad = [&] { return InputError("not an action of the exported STRIPS domain: '" + exported_action + "'"); };
  if (!e.is_list || e.items.empty() || e.items[0].is_list) throw bad();
  for (auto& it : e.items)
    if (it.is_list) throw bad();
  const std::string& name = e.items[0].atom;
  size_t nargs = e.items.size() - 1;
  auto arg = [&](size_t i) { return e.items[i + 1].atom; };
  auto suffix = [&](const std::string& prefix, std::string& rest) {
    if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size()) return false;
    rest = name.substr(prefix.size());
    return true;
  };
  std::string rest;
  for (const Move& m : kMoves)
    if (suffix(fmt::format("move-{}-", m.action), rest) && nargs == 2 && rest.find('-') == std::string::npos)
      return fmt::format("({} {})", m.action, rest);
  if (suffix("pickup-", rest) && nargs == 2 && rest.find('-') == std::string::npos)
    return fmt::format("(pickup {} {})", rest, arg(0));
  if (suffix("unlock-", rest) && nargs == 4 && rest.find('-') == std::string::npos)
    return fmt::format("(unlock {} {} {})", rest, arg(0), arg(1));
  if (suffix("wait-", rest) && nargs == 0 && rest.find('-') == std::string::npos) return fmt::format("(wait {})", rest);
  if (suffix("handover-", rest) && nargs == 3) {
    size_t dash = rest.find('-');
    if (dash != std::string::npos && dash > 0 && dash + 1 < rest.size() && rest.find('-', dash + 1) == std::string::npos)
      return fmt::format("(handover {} {} {})", rest.substr(0, dash), rest.substr(dash + 1), arg(0));
  }
  throw bad();
}

}  // namespace clips::domains::dkg
