#pragma once
// The grounded task: a domain + problem compiled for fast simulation.
//
//   Task        owns the lifted Domain/Problem, the table of dynamic atoms (one
//               bit each in a State; derived ones computed by the ground
//               rules of :derived predicates) and dynamic numeric fluents
//               (int16 slots), the folded static facts, and the ground actions.
//   GroundAction  name + argument objects, a compiled precondition, compiled
//               effects (unconditional add/delete/numeric, plus conditional
//               ones) and the set of its `active`-style trigger bit.
//   CondId      a compiled condition (precondition, goal, any formula) in an
//               expression pool; evaluated directly on state words.
//   CompiledCondition  a condition compiled after grounding (a goal, a
//               command's goal): it owns its own expression pool, so compiling
//               one never touches the task.
//
// Grounding (grounder.cpp) starts with relaxed reachability
// (reachability.hpp): only the ground actions and atoms reachable from the
// initial state are made, and GroundingOptions::max_ground_actions limits
// their real count (InputError naming it). Then two passes over those
// actions: the first finds the ground atoms and fluents some action
// changes; the second compiles everything with the rest folded as static
// (an unreachable atom is false; (has robot gem1) when the robot may never
// hold gems keeps its initial value). Predicates listed in
// GroundingOptions::keep_dynamic stay in the state even if no action changes
// them, because callers set them on copies of states (e.g. `frozen` in the
// assistance simulations). Quantifiers expand within the same limit, per
// condition. Grounding stops at GroundingOptions::deadline and before memory
// runs out (TimeLimitError, MemoryLimitError: naming the counts).
// Runtime queries live in task.cpp, successor generation in successor.cpp.
//
// Threads: a Task is immutable once its constructor returns. Every const
// member function (lookups, apply, applicable_actions, eval, compile,
// compile_text, explain_inapplicable) may be called from any number of threads
// at once on one shared Task; none of them writes to the task. A
// CompiledCondition is likewise immutable and shareable; it must not outlive
// its Task.
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pddl/ast.hpp"
#include "pddl/state.hpp"

namespace clips::pddl {

using ActionId = int;
using CondId = int;

struct GroundingOptions {
  std::set<std::string> keep_dynamic;       // predicate names kept as state bits
  std::vector<std::string> schema_order;    // enumeration order of schemas (default: declared)
  bool first_param_fastest = false;         // vary the first parameter fastest
  bool objects_by_name = false;             // order objects by name instead of declaration
  // Refuse a task with more ground actions reachable from its initial state
  // than this (the real count; reachability.hpp), and a condition whose
  // quantifiers expand to more instances. About 1 kB each: the default is ~2 GB.
  int64_t max_ground_actions = kDefaultMaxGroundActions;
  static constexpr int64_t kDefaultMaxGroundActions = 2'000'000;
  // Grounding past `deadline` throws TimeLimitError with a message starting
  // with `deadline_label`.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  std::string deadline_label = "time limit";
  // Refuse (MemoryLimitError) a grounding on course to need more memory than
  // the process has left (util::memory_headroom), at kBytesPerGroundAction
  // each: measured 1.0-1.1 kB per ground action of a 3-parameter schema,
  // task and heuristic tables included.
  bool check_memory = true;
  static constexpr int64_t kBytesPerGroundAction = 1024;
};

struct BitMatrix {
  int rows = 0, cols = 0;
  std::vector<uint8_t> cells;  // row-major
  bool get(int r, int c) const { return cells[static_cast<size_t>(r) * cols + c] != 0; }
};

struct NumericEffect {
  enum class Op : uint8_t { Assign, Increase, Decrease, ScaleUp, ScaleDown };
  Op op = Op::Assign;
  int slot = 0;
  int expr = 0;  // index into the numeric pool
};

struct EffectList {
  std::vector<int> add, del;  // atom bits
  std::vector<NumericEffect> num;
};

struct ConditionalEffect {
  CondId cond = 0;
  EffectList eff;
};

// A ground rule of a derived predicate: `head` (a derived atom's bit) holds
// in a state when `body` does (or another rule of the same atom's body).
struct Axiom {
  int head = 0;
  CondId body = 0;
};

struct GroundAction {
  int schema = 0;
  std::vector<ObjectId> args;
  CondId pre = 0;
  EffectList eff;
  std::vector<ConditionalEffect> cond_eff;
  double cost = 0;  // by the problem's :metric, else (increase (total-cost) n); 0 without either
  int trigger_bit = -1;  // a positive atom every applicable state has, or -1
};

class CompiledCondition;

class Task {
 public:
  Task(std::shared_ptr<const Domain> domain, std::shared_ptr<const Problem> problem,
       const GroundingOptions& opts = {});

  const Domain& domain() const { return *domain_; }
  const Problem& problem() const { return *problem_; }
  const GroundingOptions& options() const { return opts_; }

  // ---- layout
  int num_atoms() const { return static_cast<int>(atoms_.size()); }
  int num_fluents() const { return static_cast<int>(fluents_.size()); }
  int num_words() const { return num_words_; }
  int fluent_base() const { return atom_words_; }

  // ---- objects
  int num_objects() const { return static_cast<int>(problem_->objects.size()); }
  const std::string& object_name(ObjectId o) const { return problem_->objects[o].name; }
  std::optional<ObjectId> find_object(const std::string& name) const { return problem_->find_object(name); }
  bool object_is_a(ObjectId o, const std::string& type) const;
  std::vector<ObjectId> objects_of_type(const std::string& type) const;

  // The values the numeric fluents actions change can take in a state (16-bit
  // slots): a value beyond them is an InputError naming the fluent.
  static constexpr int64_t kMinFluent = -32768, kMaxFluent = 32767;

  // ---- atoms and fluents: dynamic ones have a bit/slot; static ones a value
  struct AtomRef {
    int bit = -1;          // >= 0 when dynamic
    bool value = false;    // the folded value when static
  };
  AtomRef atom(const std::string& pred, const std::vector<std::string>& args) const;
  AtomRef atom(PredId pred, const std::vector<ObjectId>& args) const;
  struct FluentRef {
    int slot = -1;         // >= 0 when dynamic
    int64_t value = 0;     // the folded value when static (ints)
    const BitMatrix* matrix = nullptr;  // static bit-matrix value
  };
  FluentRef fluent(const std::string& func, const std::vector<std::string>& args) const;
  FluentRef fluent(FuncId func, const std::vector<ObjectId>& args) const;
  std::string atom_str(int bit) const;
  // The predicate and objects of a dynamic atom / function and objects of a fluent.
  const std::pair<PredId, std::vector<ObjectId>>& atom_info(int bit) const { return atoms_[bit]; }
  const std::pair<FuncId, std::vector<ObjectId>>& fluent_info(int slot) const { return fluents_[slot]; }
  std::string fluent_str(int slot) const;

  bool test(const State& s, const AtomRef& a) const { return a.bit < 0 ? a.value : get_bit(s.data(), a.bit); }
  int64_t value(const State& s, const FluentRef& f) const {
    return f.slot < 0 ? f.value : get_num(s.data(), atom_words_, f.slot);
  }
  // Sets a dynamic atom (throws if it is static and the value differs).
  void set(State& s, const AtomRef& a, bool v) const;
  void set(State& s, const FluentRef& f, int64_t v) const;

  // ---- states
  State initial_state() const;
  State empty_state() const { return State{std::vector<uint64_t>(num_words_, 0)}; }
  std::string state_str(const State& s) const;  // true atoms and fluent values

  // ---- actions
  int num_actions() const { return static_cast<int>(actions_.size()); }
  const GroundAction& action(ActionId a) const { return actions_[a]; }
  std::string action_name(ActionId a) const;  // e.g. "(handover robot human key1)"
  std::optional<ActionId> find_action(const std::string& text) const;  // parses "(name args)"
  std::optional<ActionId> find_action(int schema, const std::vector<ObjectId>& args) const;

  bool applicable(ActionId a, const uint64_t* s) const;
  void apply(ActionId a, const uint64_t* src, uint64_t* dst) const;
  State apply(const State& s, ActionId a) const;
  // Applicable actions in enumeration order.
  void applicable_actions(const uint64_t* s, std::vector<ActionId>& out) const;
  std::vector<ActionId> applicable_actions(const State& s) const;

  // ---- derived predicates (:derived): atoms computed from the others
  // Derived atoms are bits of the state like the others; apply() and
  // initial_state() compute them (stratum by stratum, each a least fixpoint),
  // so conditions read them as atoms. Their rules, by stratum:
  int num_axioms() const { return static_cast<int>(axioms_.size()); }
  const Axiom& axiom(int i) const { return axioms_[static_cast<size_t>(i)]; }
  bool is_derived(int bit) const { return !derived_.empty() && derived_[static_cast<size_t>(bit)] != 0; }
  // Recomputes the derived atoms of `s` from its other atoms (after a caller
  // changed some of them, e.g. with set()).
  void evaluate_axioms(uint64_t* s) const;
  void evaluate_axioms(State& s) const { evaluate_axioms(s.data()); }

  // ---- conditions
  // Compiles a lifted condition (variables bound by `binding`, -1 = free) or a
  // PDDL formula into its own pool; the task is not changed.
  CompiledCondition compile(const Condition& c, std::vector<ObjectId> binding) const;
  CompiledCondition compile_text(const std::string& text, const std::string& label = "<condition>") const;
  // Conditions of the task's own pool: action preconditions and effect conditions.
  bool eval(CondId c, const uint64_t* s) const { return eval_in(pool_, c, s); }
  bool holds(const State& s, CondId c) const { return eval(c, s.data()); }
  bool is_const_true(CondId c) const { return c == kTrue; }
  bool is_const_false(CondId c) const { return c == kFalse; }

  // Why an action cannot be taken in `s`: the first top-level conjunct of its
  // lifted precondition that is false, printed with the action's objects; ""
  // if it is applicable.
  std::string explain_inapplicable(int schema, const std::vector<ObjectId>& args, const State& s) const;

  // Compiled expression pool (public for heuristics that inspect structure).
  struct CNode {
    // SlotConst / SlotSlot are compiled fast paths for the common comparisons
    // "fluent (+k) vs constant" and "fluent vs fluent (+k)".
    enum Op : uint8_t { True, False, Atom, NotAtom, And, Or, Not, Eq, Ne, Lt, Le, Gt, Ge, SlotConst, SlotSlot };
    Op op;
    int a = 0, b = 0;  // Atom: bit; And/Or: kids range [a, a+b); Not: kid a; Cmp: num nodes a, b;
                       // SlotConst: slot a vs constant b; SlotSlot: slot a vs slot b + k
    int c = 0;         // SlotConst/SlotSlot: comparison (Eq..Ge as 0..5) | k << 3
  };
  struct NNode {
    enum Op : uint8_t { Const, Fluent, Add, Sub, Mul, Div, Neg, GetIndex };
    Op op;
    int64_t v = 0;  // Const value; Fluent slot; GetIndex matrix index
    int a = 0, b = 0;  // Fluent: a = constant offset added to the slot's value
  };
  // A pool of compiled expression nodes; every pool starts with True, False.
  struct Pool {
    std::vector<CNode> cnodes;
    std::vector<int> ckids;
    std::vector<NNode> nnodes;
    std::vector<SourceLoc> div_locs;  // where each division was written (NNode::Div's v)
  };
  // The task's own pool (action preconditions and effect conditions).
  const CNode& cnode(CondId c) const { return pool_.cnodes[c]; }
  const std::vector<int>& ckids() const { return pool_.ckids; }

 private:
  friend class ConditionCompiler;
  friend class Grounder;
  friend class CompiledCondition;
  static constexpr CondId kTrue = 0, kFalse = 1;

  bool eval_in(const Pool& pool, CondId c, const uint64_t* s) const;
  int64_t eval_num(const Pool& pool, int n, const uint64_t* s) const;
  void apply_list(const EffectList& e, const uint64_t* src, uint64_t* dst, bool adds) const;

  std::shared_ptr<const Domain> domain_;
  std::shared_ptr<const Problem> problem_;
  GroundingOptions opts_;

  // atoms_/fluents_: dynamic ones, index = bit/slot
  std::vector<std::pair<PredId, std::vector<ObjectId>>> atoms_;
  std::vector<std::pair<FuncId, std::vector<ObjectId>>> fluents_;
  std::map<std::vector<int>, int> atom_index_;    // [pred, args...] -> bit
  std::map<std::vector<int>, int> fluent_index_;  // [func, args...] -> slot
  std::set<std::vector<int>> static_true_;        // [pred, args...] true in init
  std::map<std::vector<int>, int64_t> static_int_;
  std::map<std::vector<int>, int> static_matrix_;  // -> matrices_ index
  std::vector<BitMatrix> matrices_;
  std::set<int> dynamic_preds_;                    // predicate-level dynamic
  std::set<int> dynamic_funcs_;
  std::vector<int64_t> init_fluent_values_;        // per dynamic slot
  std::vector<int> init_bits_;
  int atom_words_ = 0, num_words_ = 0;

  std::vector<GroundAction> actions_;
  std::map<std::vector<int>, ActionId> action_index_;  // [schema, args...] -> id

  // Derived atoms: the rules by stratum (axioms_[stratum_begin_[k],
  // stratum_begin_[k+1])), a flag per bit, the mask of their bits, and per
  // derived bit the rules of its stratum that read it (CSR), to look at again
  // once it becomes true.
  std::vector<Axiom> axioms_;
  std::vector<int> stratum_begin_;
  std::vector<char> derived_;
  std::vector<uint64_t> derived_mask_;
  std::vector<int> readers_begin_, readers_;
  void prepare_axioms();
  std::vector<std::pair<int, std::vector<ActionId>>> trigger_groups_;  // bit -> actions
  std::vector<ActionId> untriggered_;
  // Preconditions flattened for speed: per action, its primitive top-level
  // conjuncts (atoms, slot comparisons) in prims_[prim_begin_[a] ..
  // prim_begin_[a+1]) and the remaining conjuncts as compiled conditions.
  std::vector<CNode> prims_;
  std::vector<int> prim_begin_;
  std::vector<int> rest_begin_;
  std::vector<CondId> rests_;
  void flatten_preconditions();
  bool test_prim(const CNode& n, const uint64_t* s) const;

  // Successor generation. The actions of each trigger group (and the
  // untriggered ones) are cut, in ascending order, into chunks of at most 64.
  // Every atom literal some precondition of a chunk requires is tested once
  // per state, and clears the chunk's actions that need the other value; only
  // the survivors test the rest of their precondition (gen_prims_: slot
  // comparisons, then the non-primitive conjuncts rests_).
  struct LitFilter {
    int bit = 0;
    uint64_t kill_if_set = 0, kill_if_clear = 0;  // chunk-local action masks
  };
  struct Chunk {
    int trigger = -1;                // bit that must be set, -1 for none
    int first = 0, count = 0;        // actions chunk_actions_[first, first + count)
    int lit_begin = 0, lit_end = 0;  // filters lit_filters_[lit_begin, lit_end)
  };
  std::vector<Chunk> chunks_;
  std::vector<ActionId> chunk_actions_;
  std::vector<LitFilter> lit_filters_;
  std::vector<CNode> gen_prims_;   // per action: [gen_begin_[a], gen_begin_[a+1])
  std::vector<int> gen_begin_;
  void build_chunks();
  bool applicable_rest(ActionId a, const uint64_t* s) const;

  // rests_ recompiled for the generator (gen_rests_[i] is rests_[i]'s root):
  // primitives inline, and a comparison of a static matrix cell at fluent
  // (+k) coordinates with a constant (the walls test) as one node; any
  // other condition defers to eval().
  struct GNode {
    enum Op : uint8_t { Prim, Prims, And, Or, Not, Cell, Cond };
    Op op = Cond;
    CNode prim{CNode::True};  // Prim
    int a = 0, b = 0;         // And/Or: kids [a, a+b) of gkids_; Prims: a conjunction of
                              // gprims_[a, a+b); Not: kid a; Cell: cells_ index; Cond: CondId
  };
  struct CellTest {
    int matrix = 0;
    int row_slot = -1, row_k = 0;  // row = value(row_slot) + row_k, or row_k when row_slot < 0
    int col_slot = -1, col_k = 0;
    CNode::Op cmp = CNode::Eq;     // cell value (-1 off the matrix)  cmp  value
    int64_t value = 0;
  };
  std::vector<GNode> gnodes_;
  std::vector<int> gkids_;
  std::vector<CNode> gprims_;
  std::vector<CellTest> cells_;
  std::vector<int> gen_rests_;
  int compile_gen(CondId c);
  bool eval_gen(int g, const uint64_t* s) const;

  Pool pool_;
};

// A condition compiled against a grounded task, with its own expression pool
// (Task::compile). Immutable: evaluate it from any thread.
class CompiledCondition {
 public:
  CondId root() const { return root_; }
  bool eval(const uint64_t* s) const { return task_->eval_in(pool_, root_, s); }
  bool holds(const State& s) const { return eval(s.data()); }
  bool is_const_true() const { return root_ == Task::kTrue; }
  bool is_const_false() const { return root_ == Task::kFalse; }
  // Structure, for heuristics that read a goal's shape.
  const Task::CNode& cnode(CondId c) const { return pool_.cnodes[c]; }
  const std::vector<int>& ckids() const { return pool_.ckids; }

 private:
  friend class Grounder;
  friend class Task;
  CompiledCondition(const Task& task, Task::Pool pool, CondId root)
      : task_(&task), pool_(std::move(pool)), root_(root) {}
  const Task* task_;
  Task::Pool pool_;
  CondId root_;
};

}  // namespace clips::pddl
