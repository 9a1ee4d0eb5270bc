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
  bool has_value(const uint64_t* s) const { return find_value(s) != nullptr; }

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

  size_t table_size() const { return num_values_; }
  size_t tree_size() const { return tree_.size(); }

 private:
  void update(const SearchResult& r);
  double learned_estimate(const uint64_t* s);

  std::shared_ptr<const model::Specification> spec_;
  std::shared_ptr<heuristics::Heuristic> h_;
  StateMap<pddl::ActionId> tree_;
  // One table for the learned values V and cached H estimates, so a lookup
  // in the lookahead searches probes one hash table, not two. H estimates
  // are kept across refine() calls: every heuristic here gives the same
  // estimates for this spec whatever root prepare() was given (the root only
  // shapes keep()).
  struct Entry {
    double v = 0;  // V(s) when has_v
    double h = 0;  // H(s) when has_h
    bool has_v = false, has_h = false;
  };
  StateMap<Entry> table_;
  size_t num_values_ = 0;  // entries with has_v
  const double* find_value(const uint64_t* s) const {
    const Entry* e = table_.find(s);
    return e && e->has_v ? &e->v : nullptr;
  }
  void set_value(const uint64_t* s, double v) {
    Entry& e = table_[s];
    if (!e.has_v) ++num_values_;
    e.has_v = true;
    e.v = v;
  }
};

}  // namespace clips::search
