#pragma once
// The VirtualHome value function: VH
// replaces real-time search by an analytic lower bound h_g that counts the
// goal items still to be moved and the fixtures still to be visited. The
// inference policies use V_g = -h_g with no search at all (n_iters = 0), and
// the utterance model's rollout runs weighted A* on it.
#include <string>
#include <vector>

#include "heuristics/heuristic.hpp"

namespace clips::domains::vh {

class VhValueHeuristic : public heuristics::Heuristic {
 public:
  explicit VhValueHeuristic(const pddl::Task& task);

  std::string name() const override { return "vh"; }
  // A lower bound per the paper, but waits and turns are not counted
  // consistently, so it is not claimed to be consistent.
  bool admissible() const override { return true; }
  bool consistent() const override { return false; }
  // Reads the goal items (GI) and goal fixtures (GF) from the goal text's
  // `placed`, `holding` and `next-to` atoms; cached per goal.
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* state) override;
  using heuristics::Heuristic::estimate;

 private:
  const pddl::Task* task_;
  std::string goal_text_;
  std::vector<int> agents_, fixtures_;
  std::vector<pddl::Task::AtomRef> nograb_;  // per agent
  std::vector<bool> fixture_in_goal_;        // per fixture index
  struct GoalItem {
    std::vector<pddl::Task::AtomRef> placed;   // per fixture
    std::vector<pddl::Task::AtomRef> holding;  // per agent
  };
  std::vector<GoalItem> items_;
  std::vector<std::vector<pddl::Task::AtomRef>> next_to_;  // [agent][fixture]
};

}  // namespace clips::domains::vh

namespace clips::domains::vh {

// VH heuristic plus the action filter used by the literal listener's A*
// (as the reference's). The filter is fixed per planning call from
// the root state: nograb flags never change during a search, and fixtures that
// hold goal items at the root are a superset of those holding them later.
class VhPlanningHeuristic : public VhValueHeuristic {
 public:
  explicit VhPlanningHeuristic(const pddl::Task& task) : VhValueHeuristic(task), task_(&task) {}
  std::string name() const override { return "vh-filtered"; }
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  bool prunes() const override { return true; }
  bool keep(pddl::ActionId a) const override { return keep_[a]; }

 private:
  const pddl::Task* task_;
  std::vector<char> keep_;
};

}  // namespace clips::domains::vh
