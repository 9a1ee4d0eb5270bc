#pragma once
// Real-Time Adaptive A* with path reuse (clips-spec.md 5.3): a Policy is the
// "solution" for one specification. It holds
//   * a value table V over states (values are NEGATIVE costs; a missing entry
//     means -H(s) from the heuristic),
//   * a reusable tree: states on previously found goal paths -> next action.
// refine(s) runs one lookahead A* from each successor of s and updates V for
// every interior node of each search tree; afterwards the Q-values of all
// applicable actions in s are fresh. Policies are copyable values (the
// assistance phase keeps refining copies of the inference policies).
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "search/astar.hpp"

namespace clips::search {

struct QValue {
  pddl::ActionId action;
  double q;  // -(cost(a) + cost-to-go of the successor); -inf for dead ends
};

struct RefineStats {
  size_t searches = 0, expanded = 0;
};

class Policy {
 public:
  Policy(std::shared_ptr<const model::Specification> spec, std::shared_ptr<heuristics::Heuristic> h);

  const model::Specification& spec() const { return *spec_; }
  std::shared_ptr<const model::Specification> spec_ptr() const { return spec_; }
  heuristics::Heuristic& heuristic() const { return *h_; }

  // V(s): table value, else -H(s).
  double value(const uint64_t* s) const;
  double value(const pddl::State& s) const { return value(s.data()); }
  bool has_value(const uint64_t* s) const { return V_.contains(s); }

  // One RTAA* policy update at s (spec REFINE). `opts` holds the budgets.
  RefineStats refine(const pddl::State& s, const SearchOptions& opts);

  // Q-values of every applicable action of the active agent in s (unfiltered,
  // in enumeration order). Reads V (or -H) of the successors; no search.
  std::vector<QValue> q_values(const pddl::State& s) const;
  // Tree action when s lies on a stored goal path, else the first action of
  // maximal Q; nullopt if every Q is -inf or nothing is applicable.
  std::optional<pddl::ActionId> best_action(const pddl::State& s) const;
  // The same, from Q-values already computed by q_values(s).
  std::optional<pddl::ActionId> best_action(const pddl::State& s, const std::vector<QValue>& qs) const;
  // Greedy rollout of best_action for at most `max_steps`, stopping at the goal.
  std::vector<pddl::ActionId> rollout(const pddl::State& s, int max_steps) const;

  size_t table_size() const { return V_.size(); }
  size_t tree_size() const { return tree_.size(); }

 private:
  void update(const SearchResult& r);
  double learned_estimate(const uint64_t* s);

  std::shared_ptr<const model::Specification> spec_;
  std::shared_ptr<heuristics::Heuristic> h_;
  StateMap<double> V_;
  StateMap<pddl::ActionId> tree_;
  // H estimates made during the current refine(): its lookahead searches
  // overlap, and H stays fixed between two prepare() calls.
  StateMap<double> h_cache_;
};

}  // namespace clips::search
