#pragma once
// LM-cut (Helmert & Domshlak 2009, "Landmarks, critical paths and
// abstractions: what's the difference anyway?"), after Fast Downward's
// lm_cut_landmarks: admissible, and on most tasks far more informative than
// h_max, so optimal A* expands far fewer states.
//
// What it reads (relaxed.hpp): per ground action its positive top-level
// preconditions, its adds and its cost. Conditional effects count as
// unconditional adds: after grounding, the turn idiom's
// `(when (next-turn ?a ?b) (active ?b))` has a static condition and is a
// plain effect already; a condition that stays dynamic only makes the
// relaxation easier, so the estimate stays admissible (less informed where
// such effects matter). Other negative preconditions and negative goal
// literals are dropped, as in h_max; numeric conditions too. A disjunctive
// goal becomes one zero-cost goal operator per DNF clause.
//
// Two strengthenings, both admissible (relaxed.hpp):
//   * actions whose negative precondition can never become true again (a
//     frozen agent's) are left out in states where it is false;
//   * turns: in a task written with the turn idiom, the turn atoms are left
//     out of the relaxation, and the alternation of turns is added back as a
//     lower bound. A landmark made only of agent X's actions needs an action
//     of X; landmarks of one agent that share no action need as many; the
//     agents alternate, so a plan has at least the turns that many actions
//     force on every agent, and every action of a plan pays at least its
//     residual cost after the cuts (what LM-cut's cost partitioning left of
//     it). So h = LM-cut + sum over agents of (their forced turns) x (the
//     least residual cost of an action of theirs usable in the state). With a
//     frozen assistant (only its wait is usable, and no landmark needs a
//     wait), every action of the principal's plan pays for one wait.
//
// Costs: the relaxation's costs are scaled to integers by the smallest factor
// 1..1000 that makes them integral (unit costs: 1; `wait` at 0.6: 5), and
// rounded down otherwise, so the value is exact for such costs and never
// above the real one.
#include <cstdint>
#include <vector>

#include "heuristics/heuristic.hpp"
#include "heuristics/relaxed.hpp"

namespace clips::heuristics {

class LmCutHeuristic : public Heuristic {
 public:
  // `turns`: leave turn atoms out and add the turn bound (the default).
  // `negations`: negative preconditions as atoms of their own (relaxed.hpp;
  // "lmcut-noneg" without).
  explicit LmCutHeuristic(bool turns = true, bool negations = true) : turns_(turns), negations_(negations) {}
  std::string name() const override {
    return std::string(turns_ ? "lmcut" : "lmcut-plain") + (negations_ ? "" : "-noneg");
  }
  bool admissible() const override { return true; }
  bool consistent() const override { return false; }
  bool estimates_depend_on_root() const override { return false; }  // the goal only
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* s) override;

  // The scale of the integer costs.
  int cost_scale() const { return scale_; }

 private:
  enum Status : uint8_t { Unreached, Reached, GoalZone, BeforeGoalZone };
  void first_exploration(const uint64_t* s);
  void incremental_exploration();
  void mark_goal_plateau();
  void second_exploration(const uint64_t* s);
  int64_t turn_bound(const uint64_t* s);
  void enqueue(int p, int64_t cost) {
    if (status_[static_cast<size_t>(p)] == Unreached || hmax_[static_cast<size_t>(p)] > cost) {
      if (status_[static_cast<size_t>(p)] == Unreached) reached_.push_back(p);
      status_[static_cast<size_t>(p)] = Reached;
      hmax_[static_cast<size_t>(p)] = cost;
      push(cost, p);
    }
  }
  void set_supporter(size_t o, int p, int64_t c) {
    supporter_[o] = p;
    supporter_cost_[o] = c;
    supported_[static_cast<size_t>(p)].push_back(static_cast<int>(o));
  }
  // A monotone queue: buckets when costs are small integers, else a heap.
  void push(int64_t c, int p);
  bool pop(int64_t& c, int& p);
  void clear_queue();

  bool turns_;
  bool negations_;
  const model::Specification* spec_ = nullptr;
  RelaxedTask r_;
  int scale_ = 1;
  int num_atoms_ = 0, num_props_ = 0, init_prop_ = 0, goal_prop_ = 0;
  // Operators (CSR): the relaxation's, then one zero-cost operator per goal clause.
  std::vector<int> op_pre_begin_, op_pre_, op_eff_begin_, op_eff_;
  std::vector<int64_t> base_cost_, cost_;
  std::vector<int> unsat0_, unsat_, supporter_;
  std::vector<int64_t> supporter_cost_;
  // Propositions (CSR): the operators they are a precondition / an effect of.
  std::vector<int> pre_of_begin_, pre_of_, eff_of_begin_, eff_of_;
  std::vector<int64_t> hmax_;
  std::vector<Status> status_;
  std::vector<int> reached_;  // propositions not Unreached in this estimate
  // Per proposition, the operators it has been the h_max supporter of in this
  // estimate (an operator whose supporter changed stays listed under the old
  // one too: readers check supporter_). The second exploration walks these
  // instead of every operator the proposition is a precondition of.
  std::vector<std::vector<int>> supported_;
  // Operators seen by the current second exploration, and those adding an
  // atom of the current goal zone (== round_).
  std::vector<uint32_t> seen_, into_zone_;
  uint32_t round_ = 0;
  // Turn bound: per agent, its actions (operator or -1, scaled cost); the
  // landmarks counted per agent; operators already in a counted landmark.
  struct AgentAction {
    int op;  // -1: no relaxed effect (a wait)
    int64_t cost;
    pddl::ActionId action;
  };
  std::vector<std::vector<AgentAction>> agent_actions_;
  std::vector<int> pure_count_, order_;
  std::vector<uint32_t> counted_;
  uint32_t estimate_stamp_ = 0;
  // Scratch.
  std::vector<int> cut_, stack_, zone_;
  // Queue.
  bool buckets_mode_ = true;
  std::vector<std::vector<int>> buckets_;
  size_t bucket_cur_ = 0, queued_ = 0;
  std::vector<std::pair<int64_t, int>> heap_;
};

}  // namespace clips::heuristics
