#pragma once
// A*: forward best-first search on the grounded task for one specification.
//
// Priority is (f, h, insertion counter), smaller first, so ties break toward
// deeper nodes and then earlier-generated ones. The goal
// test runs when a node is selected. Budgets (expansions, seconds) end the
// search with a status, never an exception. With a consistent heuristic the
// returned plan is optimal.
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "heuristics/heuristic.hpp"
#include "search/open_list.hpp"
#include "search/state_registry.hpp"

namespace clips::search {

enum class SearchStatus { Success, Failure, MaxNodes, MaxTime, MaxMemory };
std::string to_string(SearchStatus s);

struct SearchOptions {
  size_t max_nodes = std::numeric_limits<size_t>::max();  // expansions
  double max_seconds = std::numeric_limits<double>::infinity();
  // Wall-clock deadline shared by several searches (e.g. a whole RTAA* run of
  // `clips plan`): reaching it ends a search with MaxTime, like max_seconds.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // The process's resident memory (util::resident_bytes) above this ends a
  // search with MaxMemory; read every kMemoryCheckInterval expansions (A*:
  // and every 16 times as many generated nodes).
  int64_t max_memory_bytes = std::numeric_limits<int64_t>::max();
  static constexpr size_t kMemoryCheckInterval = 4096;
  bool fail_fast = true;     // stop when the best frontier node has f = +inf
  bool prune = true;         // ask the heuristic which actions to expand
  double h_weight = 1.0;     // f = g + w*h (w > 1: weighted A*)
  // Extra goal states (e.g. states on a stored optimal path): also terminal.
  std::function<bool(const uint64_t*)> extra_goal;
};

struct SearchNode {
  int parent = -1;
  pddl::ActionId action = -1;
  double g = 0;
  double h = 0;
  bool open = false;     // currently in the frontier
  bool expanded = false;
  uint32_t version = 0;  // frontier entries with another version are stale
  uint64_t counter = 0;  // insertion counter of its frontier entry
};

struct SearchResult {
  SearchStatus status = SearchStatus::Failure;
  std::vector<pddl::ActionId> plan;  // on success: root -> terminal
  double cost = 0;                   // g of the terminal node
  size_t expanded = 0, generated = 0;
  double seconds = 0;
  // The search tree, for RTAA* updates: node ids are registry ids.
  std::shared_ptr<StateRegistry> registry;
  std::vector<SearchNode> nodes;
  int terminal = -1;  // the node at the top of the frontier when search stopped
};

// The earlier of opts.deadline and `start` + opts.max_seconds (time_point::max()
// when neither is set).
std::chrono::steady_clock::time_point effective_deadline(const SearchOptions& opts,
                                                        std::chrono::steady_clock::time_point start);

// Runs A* from `start`. The heuristic must already be prepared for `spec`.
SearchResult astar(const model::Specification& spec, heuristics::Heuristic& h, const pddl::State& start,
                   const SearchOptions& opts = {});


// Buffers for callers that run many searches (RTAA* runs one per applicable
// action and step): the result's registry and nodes, the frontier and the
// successor scratch keep their capacity from one search to the next.
struct SearchWorkspace {
  SearchResult result;
  std::vector<OpenEntry> open;
  std::vector<pddl::ActionId> acts;
  std::vector<uint64_t> child;
};

// The same search as astar() above, with its result in ws.result (valid
// until the next search with `ws`).
const SearchResult& astar(const model::Specification& spec, heuristics::Heuristic& h, const pddl::State& start,
                          const SearchOptions& opts, SearchWorkspace& ws);

// Convenience: prepares `h` at `start`, then runs A*.
SearchResult plan(const model::Specification& spec, heuristics::Heuristic& h, const pddl::State& start,
                  const SearchOptions& opts = {});

}  // namespace clips::search
