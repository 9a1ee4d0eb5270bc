#pragma once
// The delete relaxation behind h_FF and LM-cut, built once per specification
// in flat arrays (operators and their preconditions, adds and the atoms they
// need, CSR-style), with two refinements for the two-agent domains clips is
// for; both are off in the plain form (`hff-plain`, the h_FF of before):
//
//   * Turns (TurnStructure). Where every action requires its agent's turn
//     atom and hands the turn on, the turn atoms are left out of the
//     relaxation (every action would otherwise need one, and one action of
//     the other agent makes it true for good), and the turns come back as a
//     count: the agents alternate, so a plan with n_X actions of agent X has
//     at least as many turns of each agent as alternation forces, and each
//     turn costs at least the agent's cheapest action (its wait). h_FF reads
//     n_X off its relaxed plan; LM-cut off its landmarks (admissibly).
//   * Dead preconditions. A negative precondition (not p) whose atom no
//     action ever deletes cannot become true once p holds: the action is
//     left out in such states (a frozen agent's actions, for example).
//   * Negations. A negative precondition (not p) that some action can make
//     true becomes an atom of its own, "not p": true where p is false, added
//     by the actions that delete p (the usual compilation of negative
//     preconditions, so still a relaxation: h_max and LM-cut stay
//     admissible). Without it a locked door is open in the relaxation, and
//     a state where the door's key was lost for good looks a few steps from
//     the goal: A* then searches every state it can reach before it stops.
//
// The goal is read as a disjunction of conjunctions of positive atoms (DNF of
// the compiled goal, other literals dropped: a relaxation), duplicate clauses
// and atoms removed.
#include <cstdint>
#include <vector>

#include "heuristics/conditions.hpp"
#include "heuristics/turns.hpp"
#include "model/spec.hpp"

namespace clips::heuristics {

struct RelaxedTask {
  struct Options {
    bool turns = false;           // leave turn atoms out and count turns
    bool dead_preconditions = false;
    bool negations = false;       // negative preconditions as atoms of their own
    bool keep_empty_ops = false;  // operators without adds (h_FF's plain form keeps them)
    bool dedup_preconditions = false;
    bool normalise_goal = false;
    // Keep only operators that add an atom the goal needs, directly or
    // through the preconditions of such operators. The others cannot change
    // h_add, h_max or LM-cut values of the goal's atoms (nothing they add is
    // read on the way to the goal), so dropping them changes no estimate,
    // nor h_FF's supporters; with turn atoms left out, it drops the actions
    // on items the goal does not involve.
    bool relevant_only = false;
  };
  Options options;
  int num_atoms = 0;        // the task's atoms, then the negation atoms
  int num_state_atoms = 0;  // the task's atoms (bits of a state)
  std::vector<int> negated;  // negation atom num_state_atoms + k is "not negated[k]"
  // Operators in action order: preconditions (positive top-level atoms) and
  // adds (unconditional, then conditional ones) in the task's order; then
  // the derived predicates' rules (zero cost, op_action -1, agent -1).
  std::vector<pddl::ActionId> op_action;
  std::vector<int> pre_begin, pre, add_begin, add;
  std::vector<double> cost;
  std::vector<int> agent;  // per operator: index into turns.agents (-1 without turns)
  // Per atom: the operators it is a precondition of (with repeats when an
  // operator lists it twice), and the operators it kills (dead preconditions).
  std::vector<int> needed_begin, needed_by, kill_begin, kill;
  std::vector<int> no_pre_ops;  // operators without preconditions, ascending
  bool positive_costs = true;   // every operator costs more than 0
  std::vector<std::vector<int>> goal_clauses;  // empty: the goal is false
  bool goal_trivial = false;                   // some clause has no atom left
  std::vector<int> goal_atoms;                 // the atoms of all clauses, once each

  // Turns (options.turns and the task follows the idiom).
  TurnStructure turns;
  bool use_turns = false;
  // Per agent: the cheapest action no state can kill, and its killable
  // actions by cost (for the cheapest action still usable in a state).
  std::vector<double> agent_safe_min;
  std::vector<std::vector<std::pair<double, pddl::ActionId>>> agent_killable;
  std::vector<int> killers_begin, killers;  // per action: atoms that kill it

  static RelaxedTask of(const model::Specification& spec, Options opts);

  // f(b) for every atom true in s, ascending: the state's bits, then the
  // negation atoms whose atom is false.
  template <class F>
  void for_each_true(const uint64_t* s, F&& f) const {
    const int words = (num_state_atoms + 63) / 64;
    for (int w = 0; w < words; ++w)
      for (uint64_t bits = s[w]; bits; bits &= bits - 1) {
        const int b = w * 64 + __builtin_ctzll(bits);
        if (b >= num_state_atoms) break;
        f(b);
      }
    for (size_t k = 0; k < negated.size(); ++k)
      if (!pddl::get_bit(s, negated[k])) f(num_state_atoms + static_cast<int>(k));
  }

  // The cheapest action of agent x usable in s (for a turn of x).
  double turn_cost(int x, const uint64_t* s) const;
  bool killed(pddl::ActionId a, const uint64_t* s) const;
};

// The least plan length whose turns give agent order[i] (i-th in turn order
// from the active agent) count[order[i]] actions, and each agent's number of
// turns in it: agents in a cycle of k act at turns i+1, i+1+k, ...
int min_turns(const std::vector<int>& order, const std::vector<int>& count, int k);
inline int turns_of(int L, int i, int k) { return L > i ? (L - 1 - i) / k + 1 : 0; }


}  // namespace clips::heuristics
