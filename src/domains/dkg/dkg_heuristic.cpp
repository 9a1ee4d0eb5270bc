#include "domains/dkg/dkg_heuristic.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>

#include "util/error.hpp"

namespace clips::domains::dkg {

using model::kInf;
using pddl::CondId;
using CNode = pddl::Task::CNode;

namespace {

// nullopt = the subformula was dropped (not a has/unlocked-by structure).
using Dnf = std::optional<std::vector<DkgClause>>;

// `dropped` is set when any part of the goal is left out.
Dnf to_dnf(const DkgMapAnalysis& m, const pddl::CompiledCondition& g, CondId c, std::optional<pddl::PredId> has,
           std::optional<pddl::PredId> ub, bool& dropped) {
  const pddl::Task& t = m.task();
  const CNode& n = g.cnode(c);
  switch (n.op) {
    case CNode::True: return std::vector<DkgClause>{DkgClause{}};
    case CNode::False: return std::vector<DkgClause>{};
    case CNode::Atom: {
      const auto& [pred, args] = t.atom_info(n.a);
      if (args.size() != 2 || !((has && pred == *has) || (ub && pred == *ub))) {
        dropped = true;
        return std::nullopt;
      }
      DkgGoalAtom a{n.a, m.index_of(args[0]), m.index_of(args[1])};
      if (a.agent < 0 || a.item < 0) {
        dropped = true;
        return std::nullopt;
      }
      return std::vector<DkgClause>{DkgClause{a}};
    }
    case CNode::And: {
      std::vector<DkgClause> acc{DkgClause{}};  // empty conjunction = true
      for (int i = 0; i < n.b; ++i) {
        Dnf kid = to_dnf(m, g, g.ckids()[n.a + i], has, ub, dropped);
        if (!kid) continue;
        std::vector<DkgClause> prod;
        for (const auto& x : acc)
          for (const auto& y : *kid) {
            DkgClause z = x;
            for (const auto& atom : y)
              if (std::find(z.begin(), z.end(), atom) == z.end()) z.push_back(atom);
            prod.push_back(std::move(z));
          }
        acc = std::move(prod);
      }
      return acc;
    }
    case CNode::Or: {
      std::vector<DkgClause> acc;  // empty disjunction = false
      for (int i = 0; i < n.b; ++i) {
        Dnf kid = to_dnf(m, g, g.ckids()[n.a + i], has, ub, dropped);
        if (kid) acc.insert(acc.end(), kid->begin(), kid->end());
      }
      return acc;
    }
    default:  // NotAtom, Not, comparisons
      dropped = true;
      return std::nullopt;
  }
}

bool in(ObjMask mask, int i) { return mask_has(mask, i); }

}  // namespace

std::vector<DkgClause> dkg_goal_clauses(const DkgMapAnalysis& map, const pddl::CompiledCondition& goal,
                                        bool* complete) {
  const auto& d = map.task().domain();
  // The goal is a conjunction of goal terms in the reference, so a goal that
  // is dropped entirely leaves an empty conjunction: one empty clause.
  bool dropped = false;
  Dnf r = to_dnf(map, goal, goal.root(), d.find_predicate("has"), d.find_predicate("unlocked-by"), dropped);
  if (complete) *complete = !dropped;
  std::vector<DkgClause> out = r ? *r : std::vector<DkgClause>{DkgClause{}};
  // Drop repeated clauses (the reference's unique! on goal terms).
  std::vector<DkgClause> uniq;
  for (auto& c : out)
    if (std::find(uniq.begin(), uniq.end(), c) == uniq.end()) uniq.push_back(std::move(c));
  return uniq;
}

DkgMinCosts dkg_min_costs(const model::Specification& spec, const DkgMapAnalysis& map) {
  DkgMinCosts c;
  const auto& prof = spec.profile();
  if (prof.default_cost >= 0) {
    // Costs from the profile, per agent, as the reference's get_action_cost
    // does (so an action that happens not to be grounded still counts).
    c.move = c.wait = c.pickup = c.unlock = kInf;
    for (int a = 0; a < map.num_agents(); ++a) {
      const std::string& ag = map.name(a);
      for (const char* mv : {"up", "down", "left", "right"}) c.move = std::min(c.move, prof.cost(ag, mv));
      c.wait = std::min(c.wait, prof.cost(ag, "wait"));
      c.pickup = std::min(c.pickup, prof.cost(ag, "pickup"));
      c.unlock = std::min(c.unlock, prof.cost(ag, "unlock"));
    }
  } else {
    c.move = std::min({spec.min_cost("up"), spec.min_cost("down"), spec.min_cost("left"), spec.min_cost("right")});
    c.wait = spec.min_cost("wait");
    c.pickup = spec.min_cost("pickup");
    c.unlock = spec.min_cost("unlock");
  }
  // With no agents or no such actions at all, 0 keeps the arithmetic finite.
  for (double* v : {&c.move, &c.wait, &c.pickup, &c.unlock})
    if (*v == kInf) *v = 0;
  return c;
}

// ============================================================== MST heuristic

DkgMstHeuristic::DkgMstHeuristic(std::shared_ptr<const DkgMapAnalysis> map, int max_recurse_iters, ItemPruning items)
    : map_(std::move(map)), max_iters_(max_recurse_iters), items_(items) {}

ObjMask dkg_idle_items(const DkgMapAnalysis& m) {
  const pddl::Task& t = m.task();
  ObjMask idle = 0;
  for (int i = m.num_agents(); i < m.first_door(); ++i)
    if (m.kind(i) == DkgMapAnalysis::Kind::Gem) idle |= mask_bit(i);
  const auto& schemas = t.domain().actions;
  for (pddl::ActionId a = 0; a < t.num_actions(); ++a) {
    const auto& ga = t.action(a);
    const std::string& nm = schemas[ga.schema].name;
    if (nm == "pickup" || nm == "handover") continue;
    for (pddl::ObjectId o : ga.args)
      if (const int i = m.index_of(o); i >= 0) idle &= ~mask_bit(i);
  }
  return idle;
}

void DkgMstHeuristic::prepare(const model::Specification& spec, const pddl::State& root) {
  // A map of another problem cannot be reused; build this problem's from the
  // state of the first planning call.
  if (!map_ || &map_->task() != &spec.task()) {
    map_ = DkgMapAnalysis::build(spec.task_ptr(), root);
    memo_.clear();
  }
  const DkgMapAnalysis& m = *map_;
  const int n = m.num_objects();
  costs_ = dkg_min_costs(spec, m);
  bool goal_complete = false;
  clauses_ = dkg_goal_clauses(m, spec.goal(), &goal_complete);
  if (idle_task_ != &m.task()) {
    idle_items_ = dkg_idle_items(m);
    idle_task_ = &m.task();
  }

  DkgStateView rv = m.read(root);
  info_.clear();
  nec_keys_ = nec_doors_ = goal_items_ = 0;
  for (const auto& cl : clauses_) {
    ClauseInfo ci;
    std::vector<int> agents, items;
    for (const auto& a : cl) {
      ci.bits.push_back(a.bit);
      if (std::find(agents.begin(), agents.end(), a.agent) == agents.end()) agents.push_back(a.agent);
      if (std::find(items.begin(), items.end(), a.item) == items.end()) items.push_back(a.item);
    }
    for (int a : agents) ci.agents |= mask_bit(a);
    for (int i : items) ci.items |= mask_bit(i);
    goal_items_ |= ci.items;
    if (!agents.empty()) {
      ci.agent = agents[0];
      ci.targets = items;
      ci.targets.insert(ci.targets.end(), agents.begin(), agents.end());
      // Pruning sets (5.6): RECURSIVE from the root with targets A ++ I.
      std::vector<int> a_then_i = agents;
      a_then_i.insert(a_then_i.end(), items.begin(), items.end());
      for (const auto& kd : m.recursive(rv, ci.agent, a_then_i, max_iters_)) {
        for (int k : kd.keys) nec_keys_ |= mask_bit(k);
        for (int d : kd.doors) nec_doors_ |= mask_bit(d);
      }
      std::vector<int> helpers;
      for (int a = 0; a < m.num_agents(); ++a)
        if (!in(ci.agents, a)) helpers.push_back(a);
      for (uint32_t sub = 0; sub < (1u << helpers.size()); ++sub) {
        ObjMask hs = 0;
        for (size_t j = 0; j < helpers.size(); ++j)
          if ((sub >> j) & 1u) hs |= mask_bit(helpers[j]);
        ci.helper_sets.push_back(hs);
      }
      std::vector<int> sig{ci.agent};
      sig.insert(sig.end(), ci.targets.begin(), ci.targets.end());
      auto it = memo_ids_.emplace(sig, static_cast<int>(memo_ids_.size())).first;
      ci.memo_id = it->second;
    }
    info_.push_back(std::move(ci));
  }

  // Per-action keep mask.
  const pddl::Task& t = m.task();
  const auto& schemas = t.domain().actions;
  keep_.assign(t.num_actions(), 1);
  // Each agent's wait cost under this specification (+inf: it cannot wait).
  std::vector<double> wait_cost(static_cast<size_t>(m.num_agents()), kInf);
  if (const int wait = t.domain().find_action("wait"); wait >= 0)
    for (int ag = 0; ag < m.num_agents(); ++ag)
      if (auto id = t.find_action(wait, {m.object(ag)})) wait_cost[static_cast<size_t>(ag)] = spec.cost(*id);
  // The item moved by pickup/handover `a`, done by `agent`.
  auto item_ok = [&](pddl::ActionId a, pddl::ObjectId agent, pddl::ObjectId o) {
    const int i = m.index_of(o);
    if (i < 0) return true;
    if (m.kind(i) == DkgMapAnalysis::Kind::Key) return in(nec_keys_, i) || in(goal_items_, i);
    // Clause 5.6 keeps every non-key item. One that the goal does not name
    // and that no other action uses (idle_items) changes nothing but its
    // own place, so a plan that takes or passes it costs no less with a wait
    // in its place whenever waiting is no dearer; searches need not try it.
    // On maps with many gems those moves multiply the states an A* search
    // walks through. A goal the clauses do not capture whole may name the
    // item elsewhere, so then every item is kept.
    if (items_ == ItemPruning::Reference || !goal_complete || in(goal_items_, i) || !in(idle_items_, i)) return true;
    const int ag = m.index_of(agent);
    return ag < 0 || ag >= m.num_agents() || spec.cost(a) < wait_cost[static_cast<size_t>(ag)];
  };
  for (pddl::ActionId a = 0; a < t.num_actions(); ++a) {
    const auto& ga = t.action(a);
    const std::string& nm = schemas[ga.schema].name;
    if (nm == "pickup" && ga.args.size() >= 2) {
      keep_[a] = item_ok(a, ga.args[0], ga.args[1]);
    } else if (nm == "handover" && ga.args.size() >= 3) {
      keep_[a] = item_ok(a, ga.args[0], ga.args[2]);
    } else if (nm == "unlock" && ga.args.size() >= 3) {
      int k = m.index_of(ga.args[1]), d = m.index_of(ga.args[2]);
      bool door_ok = d < 0 || in(nec_doors_, d);
      bool k_ok = k < 0 || in(goal_items_, k) || in(nec_keys_, k);
      keep_[a] = door_ok && k_ok;
    }
  }

  nodes_.reserve(n);
  key_.reserve(8 + 2 * n + 8);
  m.read(root.data(), view_);
}

const std::vector<ObjMask>& DkgMstHeuristic::key_door_masks(const ClauseInfo& c) {
  const DkgMapAnalysis& m = *map_;
  const int nai = m.num_agents() + m.num_items();
  key_.resize(sizeof(int) + 2 * nai + sizeof(ObjMask));
  char* p = key_.data();
  std::memcpy(p, &c.memo_id, sizeof(int));
  p += sizeof(int);
  for (int i = 0; i < nai; ++i) {
    // 0 = nowhere (consumed key); label + 1 otherwise.
    uint16_t r = view_.cell[i] < 0 ? 0 : static_cast<uint16_t>(view_.room[i] + 1);
    std::memcpy(p, &r, 2);
    p += 2;
  }
  std::memcpy(p, &view_.locked, sizeof(ObjMask));
  auto it = memo_.find(key_);
  if (it != memo_.end()) return it->second;

  if (memo_.size() > (1u << 16)) memo_.clear();  // bound memory on huge searches
  std::vector<ObjMask> masks;
  for (const auto& kd : m.recursive(view_, c.agent, c.targets, max_iters_)) {
    ObjMask mask = 0;
    for (size_t j = 0; j < kd.keys.size(); ++j) {
      if (m.locked(view_, kd.doors[j])) mask |= mask_bit(kd.keys[j]);
      mask |= mask_bit(kd.doors[j]);
    }
    if (std::find(masks.begin(), masks.end(), mask) == masks.end()) masks.push_back(mask);
  }
  return memo_.emplace(key_, std::move(masks)).first->second;
}

inline double DkgMstHeuristic::node_weight(int o) const {
  const DkgMapAnalysis& m = *map_;
  // An object with no location (consumed key) is isolated with its pendant:
  // no set holding it can be spanned.
  if (view_.cell[o] < 0) return kInf;
  switch (m.kind(o)) {
    case DkgMapAnalysis::Kind::Agent: return 0;
    case DkgMapAnalysis::Kind::Key:
    case DkgMapAnalysis::Kind::Gem: return view_.holder[o] >= 0 ? 0.0 : costs_.pickup;
    case DkgMapAnalysis::Kind::Door:
      // The distance already counts the step onto the door cell.
      return m.locked(view_, o) ? std::max(0.0, costs_.unlock - costs_.move) : 0.0;
  }
  return 0;
}

double DkgMstHeuristic::mst_weight(ObjMask objects, double bound) {
  const DkgMapAnalysis& m = *map_;
  nodes_.clear();
  double total = 0;
  for (ObjMask rest = objects; rest; rest &= rest - 1) {
    int o = mask_ctz(rest);
    const double w = node_weight(o);
    if (w == kInf) return kInf;
    total += w;
    nodes_.push_back(o);
  }
  // Edges weigh >= 0, so once the running total reaches the bound the
  // caller's minimum cannot change.
  if (total >= bound) return total;
  const size_t k = nodes_.size();
  if (k <= 1) return total;
  // Per node, in locals the compiler can keep in registers: its cell, the
  // edge_row rows to use towards other nodes and toward doors (both-door
  // edges have their own table), whether it is an agent or a door.
  constexpr size_t kMax = kObjMaskBits;  // objects are ObjMask indices
  int cell[kMax];
  const uint16_t* row[kMax];
  const uint16_t* door_row[kMax];
  bool agent[kMax], door[kMax], in_tree[kMax];
  double dist[kMax];
  for (size_t i = 0; i < k; ++i) {
    const int o = nodes_[i];
    cell[i] = view_.cell[o];
    door[i] = m.kind(o) == DkgMapAnalysis::Kind::Door;
    agent[i] = o < m.num_agents();
    row[i] = m.edge_row(cell[i], false);
    door_row[i] = door[i] ? m.edge_row(cell[i], true) : nullptr;  // read only between two doors
    in_tree[i] = false;
  }
  const double move = costs_.move, wait = costs_.wait;
  // Edge weight: room-label admission precomputed per cell pair (edge_row).
  // Between two agents no one waits; otherwise the other agent waits once
  // per move. Written as d*move + d*wait, as the reference sums it, so the
  // float values match to the last bit.
  auto weight = [&](size_t a, size_t b) {
    const uint16_t d = (door[a] && door[b] ? door_row[a] : row[a])[cell[b]];
    if (d == DkgMapAnalysis::kNoPath) return kInf;
    return agent[a] && agent[b] ? d * move : d * move + d * wait;
  };
  // Prim on the dense object graph (missing edges weigh +inf, and an MST that
  // needs one is not spanning, which is +inf too). Nodes join in the same
  // order as a textbook Prim from node 0 with ties to the lowest index, so
  // the sum is rounded in a fixed order.
  in_tree[0] = true;
  for (size_t i = 1; i < k; ++i) dist[i] = weight(0, i);
  for (size_t step = 1; step < k; ++step) {
    size_t best = k;
    double bd = kInf;
    for (size_t i = 1; i < k; ++i)
      if (!in_tree[i] && (best == k || dist[i] < bd)) best = i, bd = dist[i];
    if (bd == kInf) return kInf;
    total += bd;
    if (total >= bound) return total;
    in_tree[best] = true;
    for (size_t i = 1; i < k; ++i)
      if (!in_tree[i]) dist[i] = std::min(dist[i], weight(best, i));
  }
  return total;
}

double DkgMstHeuristic::clause_cost(const ClauseInfo& c, const uint64_t* s, double bound) {
  bool holds = true;
  for (int b : c.bits)
    if (!pddl::get_bit(s, b)) {
      holds = false;
      break;
    }
  if (holds) return 0;
  // The goal agent moving next saves the first wait of the other agent.
  const double saved = view_.active >= 0 && in(c.agents, view_.active) ? costs_.wait : 0.0;
  // Every spanning tree below holds the clause's own agents and items, so
  // their node weights bound the cost from below: a clause that cannot get
  // under `bound` is left before its key/door sets are looked up. The margin
  // keeps "cannot change the caller's minimum" safe from rounding.
  const ObjMask base = c.agents | c.items;
  const double cut = bound + saved + 1e-9;
  double lower = 0;
  for (ObjMask rest = base; rest; rest &= rest - 1) lower += node_weight(mask_ctz(rest));
  if (lower >= cut) return std::max(0.0, lower - saved);
  const auto& masks = key_door_masks(c);
  double cost = kInf;
  for (ObjMask kd : masks)
    for (ObjMask hs : c.helper_sets) cost = std::min(cost, mst_weight(base | kd | hs, std::min(cost, cut)));
  return std::max(0.0, cost - saved);
}

double DkgMstHeuristic::estimate(const uint64_t* s) {
  if (info_.empty()) return 0;
  map_->read(s, view_);
  double best = kInf;
  for (const auto& c : info_) {
    best = std::min(best, clause_cost(c, s, best));
    if (best == 0) break;
  }
  return best;
}

double DkgMstHeuristic::clause_cost(size_t c, const uint64_t* s) {
  map_->read(s, view_);
  return clause_cost(info_.at(c), s);
}

// ========================================================= distance heuristic

DkgDistanceHeuristic::DkgDistanceHeuristic(std::shared_ptr<const DkgMapAnalysis> map) : map_(std::move(map)) {}

void DkgDistanceHeuristic::prepare(const model::Specification& spec, const pddl::State& root) {
  if (!map_ || &map_->task() != &spec.task()) map_ = DkgMapAnalysis::build(spec.task_ptr(), root);
  const DkgMapAnalysis& m = *map_;
  const pddl::Task& t = m.task();
  two_agents_ = m.num_agents() == 2;

  // Cheapest action and cheapest move per agent under this specification.
  std::vector<double> cheapest(m.num_agents(), kInf), move(m.num_agents(), kInf);
  const auto& schemas = t.domain().actions;
  for (pddl::ActionId a = 0; a < t.num_actions(); ++a) {
    const auto& ga = t.action(a);
    if (ga.args.empty()) continue;
    int ag = m.index_of(ga.args[0]);
    if (ag < 0 || ag >= m.num_agents()) continue;
    cheapest[ag] = std::min(cheapest[ag], spec.cost(a));
    const std::string& nm = schemas[ga.schema].name;
    if (nm == "up" || nm == "down" || nm == "left" || nm == "right") move[ag] = std::min(move[ag], spec.cost(a));
  }
  // Without strict two-agent alternation the other agent's turns are not
  // forced, so they are not counted (0 is always a valid bound).
  auto other_cheapest = [&](int x) {
    if (!two_agents_) return 0.0;
    double c = cheapest[1 - x];
    return c == kInf ? 0.0 : c;
  };
  const int pickup = t.domain().find_action("pickup"), handover = t.domain().find_action("handover");
  auto cost_of = [&](int schema, const std::vector<pddl::ObjectId>& args) {
    if (schema < 0) return kInf;
    auto id = t.find_action(schema, args);
    return id ? spec.cost(*id) : kInf;
  };

  // Everything a (has A I) bound needs, fixed per specification.
  fill_has_ = [&, pickup, handover](HasBound& hb) {
    pddl::ObjectId A = m.object(hb.agent), I = m.object(hb.item);
    hb.agent_cheapest = two_agents_ && cheapest[hb.agent] != kInf ? cheapest[hb.agent] : 0.0;
    hb.handover_from.assign(m.num_agents(), kInf);
    for (int b = 0; b < m.num_agents(); ++b)
      if (b != hb.agent) hb.handover_from[b] = cost_of(handover, {m.object(b), A, I});
    for (int x = 0; x < m.num_agents(); ++x) {
      Picker p;
      p.agent = x;
      p.pickup = cost_of(pickup, {m.object(x), I});
      if (p.pickup == kInf) continue;  // x may never pick it up
      if (x != hb.agent) {
        p.handover = hb.handover_from[x];
        if (p.handover == kInf) continue;  // x could not pass it on
      }
      p.move = move[x];
      p.other_wait = other_cheapest(x);
      hb.pickers.push_back(p);
    }
  };
  nodes_.clear();
  kids_.clear();
  has_.clear();
  has_pred_ = t.domain().find_predicate("has");
  root_ = compile(spec.goal(), spec.goal().root());
  fill_has_ = nullptr;
  m.read(root.data(), view_);
}

int DkgDistanceHeuristic::compile(const pddl::CompiledCondition& g, CondId c) {
  const DkgMapAnalysis& m = *map_;
  const pddl::Task& t = m.task();
  const CNode& n = g.cnode(c);
  Node node;
  switch (n.op) {
    case CNode::True: node.op = Node::Zero; break;
    case CNode::False: node.op = Node::Inf; break;
    case CNode::Atom: {
      const auto& [pred, args] = t.atom_info(n.a);
      int ag = args.size() == 2 ? m.index_of(args[0]) : -1, it = args.size() == 2 ? m.index_of(args[1]) : -1;
      if (!has_pred_ || pred != *has_pred_ || ag < 0 || ag >= m.num_agents() || it < 0) break;  // 0
      HasBound hb;
      hb.bit = n.a;
      hb.agent = ag;
      hb.item = it;
      fill_has_(hb);
      node.op = Node::Has;
      node.a = static_cast<int>(has_.size());
      has_.push_back(std::move(hb));
      break;
    }
    case CNode::And:
    case CNode::Or: {
      std::vector<int> ks;
      for (int i = 0; i < n.b; ++i) ks.push_back(compile(g, g.ckids()[n.a + i]));
      node.op = n.op == CNode::And ? Node::Max : Node::Min;
      node.a = static_cast<int>(kids_.size());
      node.b = static_cast<int>(ks.size());
      kids_.insert(kids_.end(), ks.begin(), ks.end());
      break;
    }
    default: break;  // negations, comparisons: bounded by 0
  }
  nodes_.push_back(node);
  return static_cast<int>(nodes_.size()) - 1;
}

// Lower bound for (has A I) — admissibility:
//  * I held by A: the atom holds, 0.
//  * I off the grid and held by nobody (a used key): no action can give it to
//    anyone again, so +inf is exact.
//  * I held by B != A: I is off the grid, so A can only get it by B's
//    (handover B A I); if A is active, A acts once before B can. Cost >=
//    handover(B,A,I) + [A active]·cheapest(A).
//  * I on the grid at cell c: some agent X must execute (pickup X I) there,
//    after at least d_X = BFS(cell_X, c) moves (the BFS ignores doors, so it
//    only relaxes the real moves), and if X != A, later (handover X A I). So X
//    performs n_X >= d_X + 1 + [X != A] actions costing >= d_X·move(X) +
//    pickup(X,I) + [X != A]·handover(X,A,I), and the plan can end with X's
//    last one at the earliest. Turns strictly alternate, so the other agent
//    acts at least n_X - 1 times in between, plus once first if it is active
//    now, each time paying >= its cheapest action. The bound is the minimum
//    over the agents X that can pick I up (and pass it on).
// And/Or nodes take max/min of admissible bounds of their children, and atoms
// we cannot bound count 0, so the tree is admissible for the whole goal and 0
// whenever the goal holds.
//
// Consistency (h(s) <= c(s,a) + h(s')), per on-grid bound h_X:
//  * X moves: d_X drops by at most 1 (BFS triangle inequality) and the other
//    agent becomes active (+1 forced turn, offsetting the -1 turn from the
//    shorter walk), so h_X falls by at most move(X) <= c.
//  * X does anything else: d_X unchanged, the other agent becomes active:
//    h_X rises.
//  * The other agent acts (not picking I up): d_X unchanged and it is no
//    longer active, so h_X falls by its cheapest action cost <= c.
//  * A picks I up: h(s') = 0 and h(s) <= h_A = pickup(A,I) = c.
//  * B != A picks I up: h(s') = handover(B,A,I) + cheapest(A) (A is active
//    next), and h(s) <= h_B = pickup(B,I) + handover(B,A,I) + cheapest(A)
//    (d_B = 0, B active) = c + h(s').
//  * Held by B: A acting lowers h by cheapest(A) <= c; B acting raises it or
//    reaches the goal by the handover (h(s) = handover cost = c) or uses the
//    key up (h(s') = +inf).
// A minimum of consistent functions is consistent, and so is a maximum, so
// the whole tree is.
double DkgDistanceHeuristic::has_bound(const HasBound& h, const uint64_t* s) const {
  if (pddl::get_bit(s, h.bit)) return 0;
  const DkgMapAnalysis& m = *map_;
  const int ci = view_.cell[h.item];
  if (ci < 0) return kInf;
  if (int b = view_.holder[h.item]; b >= 0) {
    // Held by an agent other than the goal agent (else the atom would hold).
    if (h.handover_from[b] == kInf) return kInf;
    return h.handover_from[b] + (view_.active == h.agent ? h.agent_cheapest : 0.0);
  }
  double best = kInf;
  for (const Picker& p : h.pickers) {
    uint16_t d = m.dist(view_.cell[p.agent], ci);
    if (d == DkgMapAnalysis::kNoPath) continue;
    int n = d + 1 + (p.agent != h.agent ? 1 : 0);
    int others = n - 1 + (view_.active >= 0 && view_.active != p.agent ? 1 : 0);
    double v = (d > 0 ? d * p.move : 0.0) + p.pickup + p.handover + others * p.other_wait;
    best = std::min(best, v);
  }
  return best;
}

double DkgDistanceHeuristic::eval(int node, const uint64_t* s) {
  const Node& n = nodes_[node];
  switch (n.op) {
    case Node::Zero: return 0;
    case Node::Inf: return kInf;
    case Node::Has: return has_bound(has_[n.a], s);
    case Node::Max: {
      double v = 0;
      for (int i = 0; i < n.b; ++i) v = std::max(v, eval(kids_[n.a + i], s));
      return v;
    }
    case Node::Min: {
      double v = kInf;
      for (int i = 0; i < n.b; ++i) v = std::min(v, eval(kids_[n.a + i], s));
      return v;
    }
  }
  return 0;
}

double DkgDistanceHeuristic::estimate(const uint64_t* s) {
  if (nodes_.empty()) return 0;
  map_->read(s, view_);
  return eval(root_, s);
}

}  // namespace clips::domains::dkg
