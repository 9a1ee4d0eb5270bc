#include "search/rtaa.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "util/memory.hpp"

namespace clips::search {

using model::kInf;

Policy::Policy(std::shared_ptr<const model::Specification> spec, std::shared_ptr<heuristics::Heuristic> h,
               std::shared_ptr<StateGraph> graph)
    : spec_(std::move(spec)), h_(std::move(h)), graph_(std::move(graph)) {
  if (!graph_) graph_ = std::make_shared<StateGraph>(spec_->task_ptr());
  if (&graph_->task() != &spec_->task())
    throw std::invalid_argument("Policy: the state graph belongs to another task than the specification");
  if (h_ && !h_->estimates_depend_on_root()) estimates_ = std::make_shared<SharedEstimates>();
}

void Policy::SharedEstimates::set(int id, double h) {
  const size_t c = static_cast<size_t>(id) >> kBits;
  if (c >= chunks.size()) chunks.resize(c + 1);
  if (!chunks[c]) {
    chunks[c] = std::make_unique<double[]>(kSize);
    std::fill(chunks[c].get(), chunks[c].get() + kSize, std::numeric_limits<double>::quiet_NaN());
  }
  chunks[c][static_cast<size_t>(id) & (kSize - 1)] = h;
}

double Policy::value(const uint64_t* s) const {
  if (const double* v = find_value(s)) return *v;
  return -h_->estimate(s);
}

double Policy::learned_estimate(int id) {
  if (const Entry* r = read_entry(id); r && (r->has_v || r->has_h)) return r->has_v ? -r->value_or_h : r->value_or_h;
  double h = estimates_ ? estimates_->get(id) : std::numeric_limits<double>::quiet_NaN();
  if (std::isnan(h)) {
    h = h_->estimate(graph_->state(id));
    // An estimate cut short by the deadline (0) is used once, never cached.
    if (h_->timed_out()) return h;
    if (estimates_) estimates_->set(id, h);
  }
  Entry& e = entry(id);
  e.value_or_h = h;
  e.has_h = true;
  return h;
}

bool Policy::is_goal_entry(int id) {
  if (const Entry* r = read_entry(id); r && r->goal >= 0) return r->goal == 1;
  Entry& e = entry(id);
  e.goal = spec_->is_goal(graph_->state(id)) ? 1 : 0;
  return e.goal == 1;
}

// Buffers of the lookahead searches, one set per thread.
struct Policy::Lookahead {
  std::vector<uint8_t> keep;  // per action: expanded under this refine's pruning rule
  std::vector<LookaheadNode> nodes;
  std::vector<OpenEntry> open;
};

namespace {

// A nested refine on the same thread (not expected) falls back to private buffers.
template <class T>
struct ThreadBuffers {
  T buffers;
  bool busy = false;
};

}  // namespace

size_t Policy::search_and_update(int root, const SearchOptions& opts, bool prune, Lookahead& ws,
                                 SearchStatus& status) {
  using clock = std::chrono::steady_clock;
  // As in astar(): the clock is read every 256 expansions and every 64
  // generated nodes, and the heuristic gets the deadline too.
  const clock::time_point deadline = effective_deadline(opts, clock::now());
  const bool timed = deadline != clock::time_point::max();
  std::optional<heuristics::ScopedDeadline> heur_deadline;
  if (timed) heur_deadline.emplace(*h_, deadline);
  size_t generated = 0;
  if (++epoch_ == 0) {  // wrapped: forget every old search
    for_each_entry([](Entry& e) { e.epoch = 0; });
    epoch_ = 1;
  }
  const uint32_t epoch = epoch_;
  auto& nodes = ws.nodes;
  auto& open = ws.open;
  nodes.clear();
  open.clear();
  uint64_t counter = 0;
  size_t expanded = 0;

  auto push = [&](int id, bool fresh_counter) {
    LookaheadNode& n = nodes[static_cast<size_t>(id)];
    if (fresh_counter) n.counter = counter;
    n.open = true;
    ++n.version;
    open_push(open, OpenEntry{n.g + opts.h_weight * n.h, n.h, n.counter, id, n.version});
  };
  auto add_node = [&](int entry, int parent, pddl::ActionId a, double g) {
    const int id = static_cast<int>(nodes.size());
    const double h = learned_estimate(entry);
    Entry& e = this->entry(entry);
    e.epoch = epoch;
    e.node = id;
    graph_->prefetch(entry);  // most generated nodes are expanded soon after
    LookaheadNode n;
    n.entry = entry;
    n.parent = parent;
    n.action = a;
    n.g = g;
    n.h = h;
    nodes.push_back(n);
    return id;
  };

  push(add_node(root, -1, -1, 0.0), true);
  status = SearchStatus::Failure;
  int terminal = -1;
  while (!open.empty()) {
    const OpenEntry top = open.front();
    if (!nodes[static_cast<size_t>(top.node)].open || top.version != nodes[static_cast<size_t>(top.node)].version) {
      open_pop(open);
      continue;
    }
    const int id = top.node;
    const int eid = nodes[static_cast<size_t>(id)].entry;
    if (is_goal_entry(eid) || read_entry(eid)->tree_action >= 0) {
      status = SearchStatus::Success;
      terminal = id;
      break;
    }
    if (expanded >= opts.max_nodes) {
      status = SearchStatus::MaxNodes;
      terminal = id;
      break;
    }
    if (timed && ((expanded & 255) == 0 || h_->timed_out()) && clock::now() >= deadline) {
      status = SearchStatus::MaxTime;
      terminal = id;
      break;
    }
    if (opts.max_memory_bytes != std::numeric_limits<int64_t>::max() &&
        expanded % SearchOptions::kMemoryCheckInterval == 0 && util::resident_bytes() > opts.max_memory_bytes) {
      status = SearchStatus::MaxMemory;
      terminal = id;
      break;
    }
    if (opts.fail_fast && top.f == kInf) {
      terminal = id;
      break;
    }
    open_pop(open);
    nodes[static_cast<size_t>(id)].open = false;
    ++expanded;
    const double g0 = nodes[static_cast<size_t>(id)].g;
    bool out_of_time = false;
    const auto succ = graph_->successors(eid);
    // The children's entries lie far apart: ask for all of them before the
    // loop needs the first, so their cache misses overlap.
    for (const StateGraph::Successor sc : succ)
      if (!prune || ws.keep[static_cast<size_t>(sc.action)])
        if (const Entry* ce = read_entry(sc.child)) __builtin_prefetch(ce);
    for (const StateGraph::Successor sc : succ) {
      if (prune && !ws.keep[static_cast<size_t>(sc.action)]) continue;
      const double g = g0 + spec_->cost(sc.action);
      // A state without an entry is new to this policy, so not in this search.
      const Entry* ce = read_entry(sc.child);
      if (!ce || ce->epoch != epoch) {
        ++counter;
        push(add_node(sc.child, id, sc.action, g), true);
        if (timed && ((++generated & 63) == 0 || h_->timed_out()) && clock::now() >= deadline) {
          out_of_time = true;
          break;
        }
        continue;
      }
      const int cnode = ce->node;
      LookaheadNode& c = nodes[static_cast<size_t>(cnode)];
      if (g >= c.g) continue;
      c.parent = id;
      c.action = sc.action;
      c.g = g;
      if (c.open) {
        push(cnode, false);  // decrease-key: same h and insertion counter
      } else {
        c.h = learned_estimate(sc.child);  // reopen with a fresh estimate
        ++counter;
        push(cnode, true);
      }
    }
    if (out_of_time) {
      // Ended inside this expansion: the terminal is the node just expanded
      // (its f is at most the frontier's, so the values learned stay admissible).
      status = SearchStatus::MaxTime;
      terminal = id;
      break;
    }
  }

  // RTAA* update.
  if (status == SearchStatus::Failure) {
    for (const LookaheadNode& n : nodes) set_value(n.entry, -kInf);
    return expanded;
  }
  const LookaheadNode& t = nodes[static_cast<size_t>(terminal)];
  const double f_t = t.g + t.h;
  set_value(t.entry, -t.h);
  for (size_t id = 0; id < nodes.size(); ++id) {
    const LookaheadNode& n = nodes[id];
    if (n.open || static_cast<int>(id) == terminal) continue;  // frontier nodes keep their values
    set_value(n.entry, -(f_t - n.g));
  }
  if (status == SearchStatus::Success) {
    // Store the path root..t: each node records the action toward the goal.
    for (int id = terminal; nodes[static_cast<size_t>(id)].parent >= 0; id = nodes[static_cast<size_t>(id)].parent) {
      Entry& pe = entry(nodes[static_cast<size_t>(nodes[static_cast<size_t>(id)].parent)].entry);
      if (pe.tree_action < 0) {
        pe.tree_action = nodes[static_cast<size_t>(id)].action;
        ++tree_size_;
      }
    }
  }
  return expanded;
}

RefineStats Policy::refine(const pddl::State& s, const SearchOptions& opts) { return refine_successors(s, opts, -1); }

RefineStats Policy::refine_toward(const pddl::State& s, pddl::ActionId taken, const SearchOptions& opts) {
  if (taken < 0) throw std::invalid_argument("refine_toward: no action");
  return refine_successors(s, opts, taken);
}

RefineStats Policy::refine_successors(const pddl::State& s, const SearchOptions& opts, pddl::ActionId only) {
  RefineStats st;
  const pddl::Task& task = spec_->task();
  h_->prepare(*spec_, s);  // pruning sets from this call's starting state
  if (h_->estimates_depend_on_root())
    for_each_entry([](Entry& e) { e.has_h = false; });  // cached estimates may be stale now
  thread_local ThreadBuffers<Lookahead> tls;
  std::optional<Lookahead> own;
  Lookahead* ws = &tls.buffers;
  if (tls.busy) ws = &own.emplace();
  else tls.busy = true;
  struct Release {
    bool* flag;
    ~Release() {
      if (flag) *flag = false;
    }
  } release{ws == &tls.buffers ? &tls.busy : nullptr};
  const bool prune = opts.prune && h_->prunes();
  if (prune) {
    // The pruning rule is fixed for this refine: ask it once per action.
    ws->keep.resize(static_cast<size_t>(task.num_actions()));
    for (pddl::ActionId a = 0; a < task.num_actions(); ++a) ws->keep[static_cast<size_t>(a)] = h_->keep(a) ? 1 : 0;
  }

  std::vector<uint64_t> child(task.num_words());
  double best = -kInf;
  bool cut = false;
  for (pddl::ActionId a : task.applicable_actions(s)) {
    if (only >= 0 && a != only) continue;
    if (opts.deadline != std::chrono::steady_clock::time_point::max() &&
        std::chrono::steady_clock::now() >= opts.deadline) {
      // The run's deadline has passed: the remaining successors keep their
      // old values (or -H), as after a search stopped by its budget.
      ++st.stopped_by_budget;
      cut = true;
      break;
    }
    task.apply(a, s.data(), child.data());
    const int cid = graph_->insert(child.data());
    if (const Entry* e = read_entry(cid); e && e->has_v && e->value_or_h == -kInf) continue;
    if (is_goal_entry(cid)) {
      set_value(cid, 0);
    } else {
      ++st.searches;
      SearchStatus status;
      st.expanded += search_and_update(cid, opts, prune, *ws, status);
      if (status == SearchStatus::MaxNodes || status == SearchStatus::MaxTime || status == SearchStatus::MaxMemory)
        ++st.stopped_by_budget;
    }
    best = std::max(best, -spec_->cost(a) + value(child.data()));
  }
  if (!cut && only < 0) set_value(graph_->insert(s.data()), best);  // a partial maximum is no value
  return st;
}

RefineStats Policy::refine_step(const pddl::State& s, const SearchOptions& opts) {
  RefineStats st = refine(s, opts);
  if (!best_action(s)) {
    auto estimates = estimates_;  // still valid: the same specification and heuristic
    *this = Policy(spec_, h_, graph_);
    if (estimates) estimates_ = std::move(estimates);
    const RefineStats again = refine(s, opts);
    st.searches += again.searches;
    st.expanded += again.expanded;
    st.stopped_by_budget += again.stopped_by_budget;
  }
  return st;
}

std::vector<QValue> Policy::q_values(const pddl::State& s) const {
  const pddl::Task& task = spec_->task();
  std::vector<QValue> out;
  std::vector<uint64_t> child(task.num_words());
  for (pddl::ActionId a : task.applicable_actions(s)) {
    task.apply(a, s.data(), child.data());
    double v = spec_->is_goal(child.data()) ? (has_value(child.data()) ? *find_value(child.data()) : 0.0)
                                            : value(child.data());
    out.push_back({a, -spec_->cost(a) + v});
  }
  return out;
}

std::optional<pddl::ActionId> Policy::best_action(const pddl::State& s) const {
  if (const Entry* e = tree_entry(s.data()); e && spec_->task().applicable(e->tree_action, s.data()))
    return e->tree_action;
  return best_action(s, q_values(s));
}

std::optional<pddl::ActionId> Policy::best_action(const pddl::State& s, const std::vector<QValue>& qs) const {
  if (const Entry* e = tree_entry(s.data()); e && spec_->task().applicable(e->tree_action, s.data()))
    return e->tree_action;
  std::optional<pddl::ActionId> best;
  double bq = -kInf;
  for (const QValue& q : qs)
    if (q.q > bq) {
      bq = q.q;
      best = q.action;
    }
  return best;
}

std::vector<pddl::ActionId> Policy::rollout(const pddl::State& start, int max_steps) const {
  std::vector<pddl::ActionId> plan;
  pddl::State s = start;
  for (int i = 0; i < max_steps; ++i) {
    if (spec_->is_goal(s)) break;
    auto a = best_action(s);
    if (!a) break;
    plan.push_back(*a);
    s = spec_->task().apply(s, *a);
    if (spec_->is_goal(s)) break;
  }
  return plan;
}

}  // namespace clips::search
