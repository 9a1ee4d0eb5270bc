#pragma once
// Heuristics for Doors-Keys-Gems.
//
//   DkgMstHeuristic       the reference's DoorsKeysMSTHeuristic with its
//                         action pruning. Inference likelihoods depend on its
//                         exact values, so it is a faithful reimplementation,
//                         quirks included; it is neither proven admissible
//                         nor consistent.
//   DkgDistanceHeuristic  a simple admissible and consistent bound for
//                         (has agent item) goals, for tests and for callers
//                         that need optimality guarantees.
//
// Both take an optional shared DkgMapAnalysis (goal-independent, built once
// per problem). Without one, the first prepare() builds it from its root
// state (the state of the first planning call, as the reference does).
#include <cstdint>
#include <functional>
#include <optional>
#include <map>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "domains/dkg/dkg_map.hpp"
#include "heuristics/heuristic.hpp"

namespace clips::domains::dkg {

// A goal atom the MST heuristic understands: (has agent item) or
// (unlocked-by agent door); agent/item are DkgMapAnalysis object indices.
struct DkgGoalAtom {
  int bit = -1;  // the atom's state bit
  int agent = -1, item = -1;
  bool operator==(const DkgGoalAtom& o) const { return bit == o.bit; }
};
using DkgClause = std::vector<DkgGoalAtom>;

// Disjunctive normal form of a compiled goal over `has` and `unlocked-by`
// atoms only (5.7). Other atoms, negations and comparisons are dropped from
// their parent (as the reference's transform_goals does); a conjunction left
// empty is true (one empty clause), a disjunction left empty is false (no
// clauses). Static parts are already folded by the Task's compiler.
// `complete`, if given, tells whether nothing was dropped.
std::vector<DkgClause> dkg_goal_clauses(const DkgMapAnalysis& map, const pddl::CompiledCondition& goal,
                                        bool* complete = nullptr);

// Minimum action costs over both agents (5.5 (c)).
struct DkgMinCosts {
  double move = 1, wait = 1, pickup = 1, unlock = 1;
};
DkgMinCosts dkg_min_costs(const model::Specification& spec, const DkgMapAnalysis& map);

// Non-key items that only pickup and handover actions name (gems, in the
// paper's domain): taking or passing one changes nothing but its own place.
// Like the key rules of 5.6, this reads the action names and arguments of the
// Doors-Keys-Gems domain, not their preconditions.
ObjMask dkg_idle_items(const DkgMapAnalysis& map);

// Which pickups and handovers of non-key items A* expands.
//   Reference  all of them (as the reference).
//   Idle       not those of an item the goal does not name and no other
//              action uses, by an agent for whom waiting costs no more
//              (prepare() explains why no plan's cost is lost).
enum class ItemPruning { Reference, Idle };

class DkgMstHeuristic : public heuristics::Heuristic {
 public:
  explicit DkgMstHeuristic(std::shared_ptr<const DkgMapAnalysis> map = nullptr, int max_recurse_iters = 5,
                           ItemPruning items = ItemPruning::Idle);

  std::string name() const override { return items_ == ItemPruning::Reference ? "dkg-mst-reference" : "dkg-mst"; }
  bool admissible() const override { return false; }
  bool consistent() const override { return false; }
  // The root shapes only the pruning sets (keep()); the map analysis is fixed
  // at the first call.
  bool estimates_depend_on_root() const override { return false; }
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* state) override;
  using heuristics::Heuristic::estimate;
  bool prunes() const override { return true; }
  bool keep(pddl::ActionId a) const override { return a < static_cast<int>(keep_.size()) ? keep_[a] != 0 : true; }

  // ---- introspection (tests, callers sharing the map analysis)
  const std::shared_ptr<const DkgMapAnalysis>& map() const { return map_; }
  const std::vector<DkgClause>& clauses() const { return clauses_; }
  const DkgMinCosts& min_costs() const { return costs_; }
  // Object-index masks of the 5.6 pruning sets of the last prepare().
  ObjMask necessary_keys() const { return nec_keys_; }
  ObjMask necessary_doors() const { return nec_doors_; }
  ObjMask goal_items() const { return goal_items_; }
  // CLAUSE_COST of clause `c` of the last prepare() in `state`.
  double clause_cost(size_t c, const uint64_t* state);
  // MSTW(s, set) for an object-index mask, on the last state read. With a
  // finite `bound` it may stop early and return any value >= bound once the
  // weight is known to reach it.
  double mst_weight(ObjMask objects, double bound = std::numeric_limits<double>::infinity());

 private:
  struct ClauseInfo {
    std::vector<int> bits;     // all atoms true -> cost 0
    int agent = -1;            // A[1]
    ObjMask agents = 0;        // A
    ObjMask items = 0;         // I
    std::vector<int> targets;  // I ++ A, in clause order
    std::vector<ObjMask> helper_sets;  // every subset of the agents not in A
    int memo_id = 0;
  };
  const std::vector<ObjMask>& key_door_masks(const ClauseInfo& c);
  // CLAUSE_COST; with a finite `bound` it may return any value >= bound once
  // the clause is known not to get below it (the caller keeps a minimum).
  double clause_cost(const ClauseInfo& c, const uint64_t* state,
                     double bound = std::numeric_limits<double>::infinity());
  // An object's node weight in MSTW on the last state read (+inf: no location).
  double node_weight(int o) const;

  std::shared_ptr<const DkgMapAnalysis> map_;
  int max_iters_;
  ItemPruning items_;
  ObjMask idle_items_ = 0;
  const pddl::Task* idle_task_ = nullptr;  // the task idle_items_ was read from
  DkgMinCosts costs_;
  std::vector<DkgClause> clauses_;
  std::vector<ClauseInfo> info_;
  ObjMask nec_keys_ = 0, nec_doors_ = 0, goal_items_ = 0;
  std::vector<uint8_t> keep_;

  // Per-state scratch, reused to keep estimate() allocation-free.
  DkgStateView view_;
  std::vector<int> nodes_;

  // RECURSIVE(s, A[1], I ++ A) depends on the state only through the rooms
  // of agents and items and which doors are locked, which change rarely
  // along a search; results (as object masks {K[j] : D[j] locked} ∪ D) are
  // memoised on exactly that, per clause signature.
  std::map<std::vector<int>, int> memo_ids_;
  std::unordered_map<std::string, std::vector<ObjMask>> memo_;
  std::string key_;
};

class DkgDistanceHeuristic : public heuristics::Heuristic {
 public:
  explicit DkgDistanceHeuristic(std::shared_ptr<const DkgMapAnalysis> map = nullptr);

  std::string name() const override { return "dkg-distance"; }
  bool admissible() const override { return true; }
  bool consistent() const override { return true; }
  bool estimates_depend_on_root() const override { return false; }
  void prepare(const model::Specification& spec, const pddl::State& root) override;
  double estimate(const uint64_t* state) override;
  using heuristics::Heuristic::estimate;
  const std::shared_ptr<const DkgMapAnalysis>& map() const { return map_; }

 private:
  // The goal as a max/min tree: And -> max, Or -> min, (has a i) -> bound,
  // anything else -> 0 (always a valid lower bound), False -> +inf.
  struct Node {
    enum Op : uint8_t { Zero, Inf, Has, Max, Min } op = Zero;
    int a = 0, b = 0;  // Has: index into has_; Max/Min: kids [a, a+b) in kids_
  };
  struct Picker {  // an agent X that may pick the item up
    int agent = -1;
    double pickup = 0, handover = 0;  // handover X -> goal agent (0 when X is it)
    double move = 0;                  // X's cheapest move
    double other_wait = 0;            // cheapest action of the agent that is not X
  };
  struct HasBound {
    int bit = -1, agent = -1, item = -1;
    std::vector<Picker> pickers;
    std::vector<double> handover_from;  // per agent: (handover b agent item) cost, inf if none
    double agent_cheapest = 0;          // cheapest action of the goal agent
  };
  int compile(const pddl::CompiledCondition& goal, pddl::CondId c);
  double eval(int node, const uint64_t* s);
  double has_bound(const HasBound& h, const uint64_t* s) const;

  std::shared_ptr<const DkgMapAnalysis> map_;
  std::vector<Node> nodes_;
  std::vector<int> kids_;
  std::vector<HasBound> has_;
  std::optional<pddl::PredId> has_pred_;
  std::function<void(HasBound&)> fill_has_;  // set only while prepare() compiles
  int root_ = 0;
  bool two_agents_ = true;
  DkgStateView view_;
};

}  // namespace clips::domains::dkg
