#pragma once
// The joint plans a policy holds equally good: rollouts that break ties
// between equally valued actions every way, weighted as if each tie were
// broken uniformly at random.
//
// Where two divisions of the work cost the same (the robot fetches the rod
// and the human the wrench, or the other way round), one greedy rollout
// (Policy::rollout) keeps whichever the action order happens to favour. A
// speaker who has the goal in mind may mean either, so the speaker model asks
// for all of them. The rollout refines the policy at the states where it
// looks for ties (the Q-values of a state nobody refined are heuristic
// guesses), so it learns values as inference does; the budgets keep that
// bounded.
#include <limits>
#include <vector>

#include "search/rtaa.hpp"

namespace clips::search {

struct TiedRolloutOptions {
  int max_steps = 100;    // per rollout, as Policy::rollout
  int max_plans = 8;      // rollouts returned at most
  // States refined in all (each a REFINE: one lookahead per applicable
  // action); a state's ties are looked for only where it was refined. The
  // start state is refined with the caller's budget, the others with
  // `branch_max_nodes` expansions per lookahead (a tie there is a guess the
  // bounded search makes; the division of the work is mostly settled by the
  // first moves).
  int max_refined_states = 3;
  size_t branch_max_nodes = 4096;
  // Branch only in the first this many steps of a rollout.
  int branch_depth = 4;
  // Actions whose Q is within this of the best are tied (cost units).
  double tolerance = 1e-6;
  // A refinement looks ahead only from the successors of actions whose Q
  // before it is within this of the best (cost units; infinity: every
  // successor, the full REFINE). Values before are the policy's own (learned
  // or heuristic), so an action further behind is unlikely to tie after it;
  // 2 kept the dev halves' results and cut the instruction step by about a
  // third (docs/decisions.md).
  double refine_slack = 2.0;
  // False: no refinement at all; ties are read from the values the policy
  // holds, at every state of the first `branch_depth` steps (the assistant's
  // request rule, which runs at every decision of an episode and must not
  // search: a REFINE runs one lookahead per applicable action).
  bool refine = true;
};

struct WeightedRollout {
  double weight = 0;                     // sums to 1 over the result
  std::vector<pddl::ActionId> actions;   // from the start state
};

// Rollouts of `policy` from `s`. The first follows Policy::rollout's choices
// (the tree action, else the first best action) wherever it did not branch.
// `refine` holds the lookahead budgets of the refinements it runs.
std::vector<WeightedRollout> tied_rollouts(Policy& policy, const pddl::State& s, const TiedRolloutOptions& options,
                                           const SearchOptions& refine);

}  // namespace clips::search
