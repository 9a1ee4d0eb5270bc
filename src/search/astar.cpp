#include "search/astar.hpp"

#include <chrono>
#include <queue>
#include <tuple>

namespace clips::search {

std::string to_string(SearchStatus s) {
  switch (s) {
    case SearchStatus::Success: return "success";
    case SearchStatus::Failure: return "failure";
    case SearchStatus::MaxNodes: return "max_nodes";
    case SearchStatus::MaxTime: return "max_time";
  }
  return "?";
}

namespace {

struct Entry {
  double f, h;
  uint64_t counter;
  int node;
  uint32_t version;
  bool operator>(const Entry& o) const { return std::tie(f, h, counter) > std::tie(o.f, o.h, o.counter); }
};

}  // namespace

SearchResult astar(const model::Specification& spec, heuristics::Heuristic& heur, const pddl::State& start,
                   const SearchOptions& opts) {
  using clock = std::chrono::steady_clock;
  auto t0 = clock::now();
  const pddl::Task& task = spec.task();
  SearchResult r;
  r.registry = std::make_shared<StateRegistry>(task.num_words());
  StateRegistry& reg = *r.registry;
  auto& nodes = r.nodes;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  uint64_t counter = 0;

  auto push = [&](int id, bool fresh_counter) {
    SearchNode& n = nodes[id];
    if (fresh_counter) n.counter = counter;
    n.open = true;
    ++n.version;
    double f = n.g + opts.h_weight * n.h;
    open.push(Entry{f, n.h, n.counter, id, n.version});
  };

  int root = reg.insert(start.data());
  nodes.emplace_back();
  nodes[root].h = heur.estimate(start.data());
  push(root, true);
  r.generated = 1;

  std::vector<pddl::ActionId> acts;
  std::vector<uint64_t> child(task.num_words());
  const bool prune = opts.prune && heur.prunes();

  auto finish = [&](SearchStatus st, int term) {
    r.status = st;
    r.terminal = term;
    if (term >= 0) r.cost = nodes[term].g;
    if (st == SearchStatus::Success) {
      for (int n = term; nodes[n].parent >= 0; n = nodes[n].parent) r.plan.push_back(nodes[n].action);
      std::reverse(r.plan.begin(), r.plan.end());
    }
    r.seconds = std::chrono::duration<double>(clock::now() - t0).count();
    return r;
  };

  while (!open.empty()) {
    Entry top = open.top();
    SearchNode& best = nodes[top.node];
    if (!best.open || top.version != best.version) {
      open.pop();
      continue;
    }
    const uint64_t* s = reg.get(top.node);
    if (spec.is_goal(s) || (opts.extra_goal && opts.extra_goal(s))) return finish(SearchStatus::Success, top.node);
    if (r.expanded >= opts.max_nodes) return finish(SearchStatus::MaxNodes, top.node);
    if ((r.expanded & 255) == 0 && opts.max_seconds < std::numeric_limits<double>::infinity() &&
        std::chrono::duration<double>(clock::now() - t0).count() >= opts.max_seconds)
      return finish(SearchStatus::MaxTime, top.node);
    if (opts.fail_fast && top.f == model::kInf) return finish(SearchStatus::Failure, top.node);
    open.pop();
    int id = top.node;
    nodes[id].open = false;
    nodes[id].expanded = true;
    ++r.expanded;
    task.applicable_actions(reg.get(id), acts);
    for (pddl::ActionId a : acts) {
      if (prune && !heur.keep(a)) continue;
      task.apply(a, reg.get(id), child.data());
      double g = nodes[id].g + spec.cost(a);
      bool added = false;
      int cid = reg.insert(child.data(), &added);
      if (added) {
        nodes.emplace_back();
        SearchNode& c = nodes[cid];
        c.parent = id;
        c.action = a;
        c.g = g;
        c.h = heur.estimate(child.data());
        ++counter;
        ++r.generated;
        push(cid, true);
        continue;
      }
      SearchNode& c = nodes[cid];
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
