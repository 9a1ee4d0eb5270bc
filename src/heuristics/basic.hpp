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
//                   domain packs for the human model's policies. By default
//                   it also counts the turns the agents' alternation forces
//                   (relaxed.hpp); `hff-plain` is the form without.
#include <vector>

#include "heuristics/heuristic.hpp"
#include "heuristics/relaxed.hpp"

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
  // Per atom, its h_max cost in the state last estimated (where the goal did
  // not hold there: the estimate stops at a goal state).
  const std::vector<double>& atom_costs() const { return atom_cost_; }

 private:
  const model::Specification* spec_ = nullptr;
  Relaxation r_;
  std::vector<double> atom_cost_, act_cost_;
  std::vector<int> unsat_;
};

class FFHeuristic : public Heuristic {
 public:
  // `turns`: the turn-aware form ("hff", the default of generic packs; see
  // relaxed.hpp): turn atoms left out of the relaxation, the relaxed plan's
  // actions counted per agent and the turns alternation forces added at each
  // agent's cheapest usable action, and actions whose negative precondition
  // can never become true again left out. Without: the plain h_FF
  // ("hff-plain"), values identical to the h_FF clips used before.
  // `negations` (turn-aware form only): negative preconditions as atoms of
  // their own ("hff"; "hff-noneg" without, the hff of before them).
  explicit FFHeuristic(bool turns = true, bool negations = true) : turns_(turns), negations_(turns && negations) {}
  std::string name() const override { return !turns_ ? "hff-plain" : negations_ ? "hff" : "hff-noneg"; }
  bool admissible() const override { return false; }
  bool consistent() const override { return false; }
  bool estimates_depend_on_root() const override { return false; }
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* s) override;

 private:
  void process(int b, double c);
  void relax(int op);
  bool turns_;
  bool negations_;
  const model::Specification* spec_ = nullptr;
  RelaxedTask r_;
  std::vector<double> atom_cost_, act_cost_;
  std::vector<int> unsat_, unsat0_, supporter_;
  std::vector<char> is_goal_atom_;
  // The queue of (h_add cost, atom): a heap, or, when every cost is a
  // positive multiple of 1/scale_, buckets of that width, each sorted when
  // its turn comes (the heap's order exactly: nothing enters the bucket being
  // emptied), with the heap for costs past the last bucket.
  void push(double c, int b);
  std::vector<std::pair<double, int>> heap_;
  bool buckets_mode_ = false;
  double bucket_scale_ = 1;
  std::vector<std::vector<std::pair<double, int>>> buckets_;
  size_t bucket_cur_ = 0, bucket_top_ = 0;  // first bucket not yet emptied; one past the last used
  std::vector<int> zero_, open_, count_, order_;
  std::vector<uint32_t> atom_mark_, op_mark_;
  uint32_t stamp_ = 0;
  int goal_left_ = 0;
};

}  // namespace clips::heuristics
