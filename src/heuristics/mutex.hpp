#pragma once
// Mutex pairs of a grounded task by h^2 reachability (Haslum & Geffner 2000)
// from its initial state: two atoms are mutex when no state reachable from
// there makes both true. Computed on a relaxation of the task (positive
// top-level preconditions only, conditional adds counted as adds and
// conditional deletes as not deleting), which can only find more pairs
// reachable, so every pair it calls mutex is one. Used to recognise goal
// clauses no plan can reach (a command asking for an item in two hands),
// which a delete relaxation cannot see and a search can only fail on after
// exhausting its budget.
//
// Which states it speaks for: those reachable from the initial state, also
// with atoms no action adds set on top (the `frozen` of assistance and
// literal planning): such atoms only take actions away, so they never make a
// pair reachable. Pairs with an atom unreachable from the initial state are
// never called mutex, nor pairs with a derived atom (:derived).
#include <cstdint>
#include <memory>
#include <vector>

#include "pddl/task.hpp"

namespace clips::heuristics {

class MutexTable {
 public:
  // The table of `task`, computed on first use and shared (thread-safe);
  // an empty table (no pair mutex) for tasks above `max_atoms` atoms.
  static std::shared_ptr<const MutexTable> of(const std::shared_ptr<const pddl::Task>& task,
                                              int max_atoms = 4096);
  explicit MutexTable(const pddl::Task& task, int max_atoms = 4096);
  bool mutex(int p, int q) const {
    if (empty_) return false;
    return reach1(p) && reach1(q) && !reach2(p, q);
  }
  // Whether some two atoms of the set are mutex.
  bool any_mutex(const std::vector<int>& atoms) const;

 private:
  bool reach1(int p) const { return reach2(p, p); }
  bool reach2(int p, int q) const {
    return (rows_[static_cast<size_t>(p) * words_ + (static_cast<size_t>(q) >> 6)] >> (q & 63)) & 1u;
  }
  bool empty_ = true;
  size_t words_ = 0;
  std::vector<uint64_t> rows_;  // per atom, the atoms reachable together with it
};

}  // namespace clips::heuristics
