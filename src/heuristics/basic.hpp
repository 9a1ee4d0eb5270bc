#pragma once
// Domain-independent heuristics.
//   BlindHeuristic  0 everywhere (A* becomes uniform-cost search); admissible.
//   HMaxHeuristic   h_max over a relaxation that keeps only the positive atoms
//                   of each precondition's top-level conjunction and treats
//                   conditional effects as unconditional. Ignoring conditions
//                   only makes the task easier, so h_max of the relaxation is
//                   admissible and consistent for the real task.
//   FFHeuristic     h_FF over the same relaxation: the cost of a relaxed plan
//                   extracted from h_add's best supporters. Not admissible
//                   (it may overestimate), but it counts every subgoal, where
//                   h_max sees only the most expensive one, so it tells apart
//                   actions that h_max values alike; the default of generic
//                   domain packs for the human model's policies.
#include <vector>

#include "heuristics/heuristic.hpp"

namespace clips::heuristics {

class BlindHeuristic : public Heuristic {
 public:
  std::string name() const override { return "blind"; }
  bool admissible() const override { return true; }
  bool consistent() const override { return true; }
  void prepare(const model::Specification&, const pddl::State&) override {}
  double estimate(const uint64_t*) override { return 0; }
  bool estimates_depend_on_root() const override { return false; }
};

// The delete relaxation both h_max and h_FF evaluate, built once per
// specification: per action its positive top-level preconditions, its adds
// (conditional ones included) and its cost; per atom the actions needing it;
// the goal as clauses over positive atoms.
struct Relaxation {
  std::vector<std::vector<int>> pre, add;
  std::vector<double> cost;
  std::vector<std::vector<int>> needed_by;  // atom -> actions with it as a precondition
  std::vector<std::vector<int>> goal_clauses;
  static Relaxation of(const model::Specification& spec);
};

class HMaxHeuristic : public Heuristic {
 public:
  std::string name() const override { return "hmax"; }
  bool admissible() const override { return true; }
  bool consistent() const override { return true; }
  bool estimates_depend_on_root() const override { return false; }  // the goal only
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* s) override;

 private:
  const model::Specification* spec_ = nullptr;
  Relaxation r_;
  std::vector<double> atom_cost_, act_cost_;
  std::vector<int> unsat_;
};

class FFHeuristic : public Heuristic {
 public:
  std::string name() const override { return "hff"; }
  bool admissible() const override { return false; }
  bool consistent() const override { return false; }
  bool estimates_depend_on_root() const override { return false; }
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* s) override;

 private:
  const model::Specification* spec_ = nullptr;
  Relaxation r_;
  std::vector<double> atom_cost_, act_cost_;
  std::vector<int> unsat_, supporter_;
  std::vector<char> in_plan_, atom_done_;
};

}  // namespace clips::heuristics
