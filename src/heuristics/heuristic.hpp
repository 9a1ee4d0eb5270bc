#pragma once
// Heuristics estimate the cost to reach a specification's goal from a state.
// Like Fast Downward's, each is a small class with one estimate method and
// declared properties (which tests check); like SymbolicPlanners', it has a
// precompute step per planning call (`prepare`) kept out of the hot path.
//
// A heuristic may also prune goal-irrelevant actions during search
// (clips-spec.md 5.6): A* asks keep() for each applicable action it expands.
#include <string>

#include "model/spec.hpp"

namespace clips::heuristics {

class Heuristic {
 public:
  virtual ~Heuristic() = default;
  virtual std::string name() const = 0;
  virtual bool admissible() const = 0;
  virtual bool consistent() const = 0;
  // Called once per planning call with the specification and the state the
  // call starts from (goal-specific precomputation, pruning sets).
  virtual void prepare(const model::Specification& spec, const pddl::State& root) = 0;
  // Estimated cost-to-go; model::kInf for a recognised dead end.
  virtual double estimate(const uint64_t* state) = 0;
  double estimate(const pddl::State& s) { return estimate(s.data()); }
  // Whether estimate() can change when prepare() is called again with the
  // same specification and another root. RTAA* policies cache estimates
  // across refinements only when it cannot; the default is the safe answer.
  virtual bool estimates_depend_on_root() const { return true; }
  // Action pruning inside search (default: keep everything).
  virtual bool prunes() const { return false; }
  virtual bool keep(pddl::ActionId) const { return true; }
};

}  // namespace clips::heuristics
