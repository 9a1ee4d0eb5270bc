#include "search/astar.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>

#include "util/memory.hpp"

namespace clips::search {

std::string to_string(SearchStatus s) {
  switch (s) {
    case SearchStatus::Success: return "success";
    case SearchStatus::Failure: return "failure";
    case SearchStatus::MaxNodes: return "max_nodes";
    case SearchStatus::MaxTime: return "max_time";
    case SearchStatus::MaxMemory: return "max_memory";
  }
  return "?";
}


std::chrono::steady_clock::time_point effective_deadline(const SearchOptions& opts,
                                                        std::chrono::steady_clock::time_point start) {
  using clock = std::chrono::steady_clock;
  clock::time_point d = opts.deadline;
  // Beyond about 30 years the sum could overflow the clock's range: no limit then.
  if (opts.max_seconds <= 0) {
    d = std::min(d, start);  // no time at all
  } else if (opts.max_seconds < 1e9) {
    const auto budget = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(opts.max_seconds));
    d = std::min(d, start + budget);
  }
  return d;
}

SearchResult astar(const model::Specification& spec, heuristics::Heuristic& heur, const pddl::State& start,
                   const SearchOptions& opts) {
  SearchWorkspace ws;
  astar(spec, heur, start, opts, ws);
  return std::move(ws.result);
}

const SearchResult& astar(const model::Specification& spec, heuristics::Heuristic& heur, const pddl::State& start,
                          const SearchOptions& opts, SearchWorkspace& ws) {
  using clock = std::chrono::steady_clock;
  auto t0 = clock::now();
  const pddl::Task& task = spec.task();
  SearchResult& r = ws.result;
  // Reuse the previous registry unless someone else still holds it.
  std::shared_ptr<StateRegistry> registry = std::move(r.registry);
  if (registry && registry.use_count() == 1 && registry->words() == task.num_words()) registry->clear();
  else registry = std::make_shared<StateRegistry>(task.num_words());
  std::vector<SearchNode> nodes = std::move(r.nodes);
  std::vector<pddl::ActionId> plan = std::move(r.plan);
  nodes.clear();
  plan.clear();
  r = SearchResult{};
  r.registry = std::move(registry);
  r.nodes = std::move(nodes);
  r.plan = std::move(plan);
  StateRegistry& reg = *r.registry;
  auto& nodes_ref = r.nodes;
  auto& open = ws.open;
  open.clear();
  uint64_t counter = 0;

  auto push = [&](int id, bool fresh_counter) {
    SearchNode& n = nodes_ref[id];
    if (fresh_counter) n.counter = counter;
    n.open = true;
    ++n.version;
    double f = n.g + opts.h_weight * n.h;
    open_push(open, OpenEntry{f, n.h, n.counter, id, n.version});
  };
  auto pop = [&] { open_pop(open); };

  // Time limits: one deadline (the earlier of max_seconds and opts.deadline),
  // read every 256 expansions and every 64 generated nodes, since one
  // expansion of a large grounding generates thousands of children; the
  // heuristic gets it too, for estimates that are long by themselves.
  const clock::time_point deadline = effective_deadline(opts, t0);
  const bool timed = deadline != clock::time_point::max();
  const bool memory_capped = opts.max_memory_bytes != std::numeric_limits<int64_t>::max();
  std::optional<heuristics::ScopedDeadline> heur_deadline;
  if (timed) heur_deadline.emplace(heur, deadline);

  int root = reg.insert(start.data());
  nodes_ref.emplace_back();
  nodes_ref[root].h = heur.estimate(start.data());
  push(root, true);
  r.generated = 1;

  std::vector<pddl::ActionId>& acts = ws.acts;
  std::vector<uint64_t>& child = ws.child;
  child.resize(task.num_words());
  const bool prune = opts.prune && heur.prunes();

  auto finish = [&](SearchStatus st, int term) -> const SearchResult& {
    r.status = st;
    r.terminal = term;
    if (term >= 0) r.cost = nodes_ref[term].g;
    if (st == SearchStatus::Success) {
      for (int n = term; nodes_ref[n].parent >= 0; n = nodes_ref[n].parent) r.plan.push_back(nodes_ref[n].action);
      std::reverse(r.plan.begin(), r.plan.end());
    }
    r.seconds = std::chrono::duration<double>(clock::now() - t0).count();
    return r;
  };

  while (!open.empty()) {
    const OpenEntry top = open.front();
    SearchNode& best = nodes_ref[top.node];
    if (!best.open || top.version != best.version) {
      pop();
      continue;
    }
    const uint64_t* s = reg.get(top.node);
    if (spec.is_goal(s) || (opts.extra_goal && opts.extra_goal(s))) return finish(SearchStatus::Success, top.node);
    if (r.expanded >= opts.max_nodes) return finish(SearchStatus::MaxNodes, top.node);
    if (timed && ((r.expanded & 255) == 0 || heur.timed_out()) && clock::now() >= deadline)
      return finish(SearchStatus::MaxTime, top.node);
    if (memory_capped && r.expanded % SearchOptions::kMemoryCheckInterval == 0 &&
        util::resident_bytes() > opts.max_memory_bytes)
      return finish(SearchStatus::MaxMemory, top.node);
    if (opts.fail_fast && top.f == model::kInf) return finish(SearchStatus::Failure, top.node);
    pop();
    const int id = top.node;
    best.open = false;
    best.expanded = true;
    ++r.expanded;
    task.applicable_actions(reg.get(id), acts);
    for (pddl::ActionId a : acts) {
      if (prune && !heur.keep(a)) continue;
      task.apply(a, reg.get(id), child.data());
      double g = nodes_ref[id].g + spec.cost(a);
      bool added = false;
      int cid = reg.insert(child.data(), &added);
      if (added) {
        nodes_ref.emplace_back();
        SearchNode& c = nodes_ref[cid];
        c.parent = id;
        c.action = a;
        c.g = g;
        c.h = heur.estimate(child.data());
        ++counter;
        ++r.generated;
        push(cid, true);
        if (timed && ((r.generated & 63) == 0 || heur.timed_out()) && clock::now() >= deadline)
          return finish(SearchStatus::MaxTime, id);
        // Wide tasks generate thousands of children per expansion: also read
        // the memory every kMemoryCheckInterval * 16 generated nodes.
        if (memory_capped && r.generated % (SearchOptions::kMemoryCheckInterval * 16) == 0 &&
            util::resident_bytes() > opts.max_memory_bytes)
          return finish(SearchStatus::MaxMemory, id);
        continue;
      }
      SearchNode& c = nodes_ref[cid];
      if (g >= c.g) continue;
      c.parent = id;
      c.action = a;
      c.g = g;
      if (c.open) {
        push(cid, false);  // decrease-key: same h and insertion counter
      } else {
        c.h = heur.estimate(reg.get(cid));  // reopen with a fresh estimate
        ++counter;
        push(cid, true);
      }
    }
  }
  return finish(SearchStatus::Failure, -1);
}

SearchResult plan(const model::Specification& spec, heuristics::Heuristic& h, const pddl::State& start,
                  const SearchOptions& opts) {
  h.prepare(spec, start);
  return astar(spec, h, start, opts);
}

}  // namespace clips::search
