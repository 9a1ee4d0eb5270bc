#pragma once
// Relaxed reachability of a lifted task, as a standard translator grounds:
// from the initial state (static facts included), with delete effects,
// negative literals and numeric conditions ignored, which ground atoms can
// ever become true and which ground actions can ever be applicable. Only
// those are grounded, so the size limit counts what a plan could use, never
// a cross product of parameter types that the facts rule out.
//
// Each action schema becomes rules "action(params) <- its precondition's
// positive atoms" (one per alternative of the precondition's DNF over atoms,
// existentials included, with (= ?x ?y) and (not (= ?x ?y)) as
// constraints), whose heads also add its unconditional effects; each
// conditional or universal effect rules "add <- action(params), its
// condition's positive atoms"; each :derived rule "p(params) <- its
// condition's positive atoms". Rules fire by
// a semi-naive join: every new atom is matched against the rule bodies that
// name its predicate and joined with the atoms already processed. Anything
// left out (a disjunction, a negation, a numeric test) only makes more atoms
// and actions reachable, so nothing a real plan reaches is lost.
#include <chrono>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "pddl/ast.hpp"

namespace clips::pddl {

struct ReachabilityLimits {
  int64_t max_actions = 0;  // more reachable ground actions: InputError naming the counts
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  std::string deadline_label = "time limit";
  bool check_memory = true;
  int64_t bytes_per_action = 1024;  // what each will cost once grounded (GroundingOptions)
};

// Ground atoms as [pred, args...] keys in one flat table.
class AtomTable {
 public:
  // The id of the atom, or -1.
  int find(int pred, const ObjectId* args, int n) const;
  int find(int pred, const std::vector<ObjectId>& args) const {
    return find(pred, args.data(), static_cast<int>(args.size()));
  }
  // The id of the atom, adding it when new (*added then set).
  int insert(int pred, const ObjectId* args, int n, bool* added);
  int size() const { return static_cast<int>(begin_.size()); }
  int pred(int id) const { return data_[static_cast<size_t>(begin_[static_cast<size_t>(id)])]; }
  int arity(int id) const { return len_[static_cast<size_t>(id)]; }
  const ObjectId* args(int id) const { return data_.data() + begin_[static_cast<size_t>(id)] + 1; }
  size_t bytes() const { return data_.capacity() * 4 + begin_.capacity() * 4 + len_.capacity() + table_.capacity() * 4; }

 private:
  uint64_t hash(int pred, const ObjectId* args, int n) const;
  void grow();
  std::vector<int> data_;        // pred, args... per atom
  std::vector<int> begin_;       // per atom: offset in data_
  std::vector<uint8_t> len_;     // per atom: arity
  std::vector<int> table_ = std::vector<int>(1024, -1);  // open addressing: atom id or -1
  std::vector<uint64_t> hashes_;
};

struct Reachable {
  AtomTable atoms;  // reachable atoms of the domain's predicates (derived ones too)
  // Per action schema, the argument tuples of its reachable ground actions
  // (arity each, flat), in the order they were found.
  std::vector<std::vector<ObjectId>> tuples;
  std::vector<int64_t> counts;  // per action schema: its reachable ground actions
  int64_t num_actions = 0;
  bool reached(PredId p, const std::vector<ObjectId>& args) const { return atoms.find(p, args) >= 0; }
};

// `keep_all`: predicates every atom of which counts as reachable (set by
// callers on copies of states).
Reachable explore_reachable(const Domain& d, const Problem& p, const std::set<PredId>& keep_all,
                            const ReachabilityLimits& limits);

}  // namespace clips::pddl
