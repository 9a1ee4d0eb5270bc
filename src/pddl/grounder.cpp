// Grounding: lifted domain + problem -> Task (two passes, see task.hpp), and
// the compilation of conditions into expression pools, which grounding shares
// with Task::compile.
#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>

#include "pddl/parser.hpp"
#include "pddl/reachability.hpp"
#include "pddl/task.hpp"
#include "pddl/task_inline.hpp"
#include "util/memory.hpp"

namespace clips::pddl {

using detail::key_of;

namespace {

struct InitValue {
  bool is_matrix = false;
  int64_t i = 0;
  BitMatrix m;
};

// a op b (op one of + - * /, b != 0 for /) on constants from the input:
// overflow is an input error at `loc` instead of undefined behaviour.
int64_t checked(char op, int64_t a, int64_t b, const SourceLoc& loc) {
  int64_t v = 0;
  bool overflow = op == '+'   ? __builtin_add_overflow(a, b, &v)
                  : op == '-' ? __builtin_sub_overflow(a, b, &v)
                  : op == '*' ? __builtin_mul_overflow(a, b, &v)
                              : (a == std::numeric_limits<int64_t>::min() && b == -1);
  if (overflow) throw InputError(loc, "integer overflow: the result is beyond the 64-bit integer range");
  return op == '/' ? a / b : v;
}

}  // namespace

// Compiles conditions and numeric expressions into a pool. On its own it reads
// a finished task and never changes it (Task::compile); the Grounder below
// extends it to intern state variables while it builds the task.
class ConditionCompiler {
 public:
  ConditionCompiler(const Task& t, Task::Pool& pool) : ct_(t), d_(*t.domain_), p_(*t.problem_), pool_(pool) {}
  virtual ~ConditionCompiler() = default;

 protected:
  // Every kTupleCheckInterval tuples of an enumeration (`visited` so far in
  // it), the grounder checks its budgets; a finished task's compiler does not.
  static constexpr uint64_t kTupleCheckInterval = 4096;
  virtual void on_tuples(uint64_t /*visited*/) {}

  // The bit of a dynamic ground atom, -1 when it is folded (static). A finished
  // task answers from its tables; the Grounder interns new ones.
  virtual int atom_bit(PredId pred, const std::vector<ObjectId>& args) {
    auto it = ct_.atom_index_.find(key_of(pred, args));
    return it == ct_.atom_index_.end() ? -1 : it->second;
  }
  virtual int fluent_slot(FuncId f, const std::vector<ObjectId>& args) {
    auto it = ct_.fluent_index_.find(key_of(f, args));
    return it == ct_.fluent_index_.end() ? -1 : it->second;
  }

  // ------------------------------------------------------------ objects
  std::vector<ObjectId> objects_of(TypeId t) const {
    std::vector<ObjectId> out;
    for (size_t i = 0; i < p_.objects.size(); ++i)
      if (d_.is_subtype(p_.objects[i].type, t)) out.push_back(static_cast<ObjectId>(i));
    if (ct_.opts_.objects_by_name)
      std::sort(out.begin(), out.end(), [&](ObjectId a, ObjectId b) { return p_.objects[a].name < p_.objects[b].name; });
    return out;
  }

  // f(tuple) for every tuple of objects of `types`, until f returns false.
  template <class F>
  void for_each_tuple(const std::vector<TypeId>& types, F&& f, bool first_fastest = false) {
    std::vector<std::vector<ObjectId>> doms;
    for (auto t : types) {
      doms.push_back(objects_of(t));
      if (doms.back().empty()) return;
    }
    std::vector<size_t> idx(types.size(), 0);
    std::vector<ObjectId> tuple(types.size());
    for (uint64_t visited = 1;; ++visited) {
      for (size_t i = 0; i < types.size(); ++i) tuple[i] = doms[i][idx[i]];
      if (!f(tuple)) return;
      if (visited % kTupleCheckInterval == 0) on_tuples(visited);
      // odometer increment: last position fastest unless first_fastest
      size_t n = types.size();
      size_t k = 0;
      for (; k < n; ++k) {
        size_t pos = first_fastest ? k : n - 1 - k;
        if (++idx[pos] < doms[pos].size()) break;
        idx[pos] = 0;
      }
      if (k == n) return;
    }
  }

 public:
  // ------------------------------------------------------------ compilation
  using CNode = Task::CNode;
  using NNode = Task::NNode;

  int add_c(CNode n) {
    pool_.cnodes.push_back(n);
    return static_cast<int>(pool_.cnodes.size() - 1);
  }
  int add_n(NNode n) {
    pool_.nnodes.push_back(n);
    return static_cast<int>(pool_.nnodes.size() - 1);
  }
  bool is_const_n(int n) const { return pool_.nnodes[n].op == NNode::Const; }

  ObjectId resolve(const TermRef& r, const std::vector<ObjectId>& b) const {
    return r.is_var ? b[r.index] : r.index;
  }
  bool args_fit(const std::vector<TypeId>& types, const std::vector<ObjectId>& args) const {
    for (size_t i = 0; i < args.size(); ++i)
      if (!d_.is_subtype(p_.objects[args[i]].type, types[i])) return false;
    return true;
  }

  int negate(int c) {
    CNode n = pool_.cnodes[c];
    switch (n.op) {
      case CNode::True: return Task::kFalse;
      case CNode::False: return Task::kTrue;
      case CNode::Atom: return add_c({CNode::NotAtom, n.a, 0});
      case CNode::NotAtom: return add_c({CNode::Atom, n.a, 0});
      case CNode::Not: return n.a;
      case CNode::Eq: return add_c({CNode::Ne, n.a, n.b});
      case CNode::Ne: return add_c({CNode::Eq, n.a, n.b});
      case CNode::Lt: return add_c({CNode::Ge, n.a, n.b});
      case CNode::Ge: return add_c({CNode::Lt, n.a, n.b});
      case CNode::Le: return add_c({CNode::Gt, n.a, n.b});
      case CNode::Gt: return add_c({CNode::Le, n.a, n.b});
      case CNode::SlotConst: case CNode::SlotSlot: {
        static const int flip[6] = {1, 0, 5, 4, 3, 2};  // Eq<->Ne, Lt<->Ge, Le<->Gt
        CNode m = n;
        m.c = (n.c & ~7) | flip[n.c & 7];
        return add_c(m);
      }
      default: return add_c({CNode::Not, c, 0});
    }
  }

  // A string equal for structurally equal conditions of the pool (atoms by
  // bit, junctions by their kids; other nodes by their own fields, which
  // tells apart equal comparisons of distinct numeric nodes: safe).
  std::string structure(int c) const {
    const CNode& n = pool_.cnodes[c];
    std::string out = std::to_string(static_cast<int>(n.op));
    if (n.op == CNode::And || n.op == CNode::Or) {
      out += '(';
      for (int i = 0; i < n.b; ++i) out += structure(pool_.ckids[n.a + i]) + ',';
      return out + ')';
    }
    if (n.op == CNode::Not) return out + '(' + structure(n.a) + ')';
    return out + ':' + std::to_string(n.a) + ':' + std::to_string(n.b) + ':' + std::to_string(n.c);
  }

  int junction(bool is_and, std::vector<int> kids) {
    std::vector<int> keep;
    for (int k : kids) {
      if (k == (is_and ? Task::kTrue : Task::kFalse)) continue;
      if (k == (is_and ? Task::kFalse : Task::kTrue)) return k;
      const CNode& n = pool_.cnodes[k];
      if (n.op == (is_and ? CNode::And : CNode::Or)) {  // flatten nested
        for (int i = 0; i < n.b; ++i) keep.push_back(pool_.ckids[n.a + i]);
      } else {
        keep.push_back(k);
      }
    }
    if (keep.empty()) return is_and ? Task::kTrue : Task::kFalse;
    // p and (not p): a conjunction that never holds, a disjunction that always does.
    if (keep.size() > 1) {
      std::vector<int> pos, neg;
      for (int k : keep) {
        const CNode& n = pool_.cnodes[k];
        if (n.op == CNode::Atom) pos.push_back(n.a);
        if (n.op == CNode::NotAtom) neg.push_back(n.a);
      }
      if (!pos.empty() && !neg.empty()) {
        std::sort(pos.begin(), pos.end());
        for (int b : neg)
          if (std::binary_search(pos.begin(), pos.end(), b)) return is_and ? Task::kFalse : Task::kTrue;
      }
    }
    // A disjunction repeats the same kid once per binding of variables its
    // atoms do not read (an existential command goal over ?station1 ...):
    // keep the first of structurally equal kids (the value cannot change).
    if (!is_and && keep.size() > 1) {
      std::vector<int> unique;
      std::set<std::string> seen;
      for (int k : keep)
        if (seen.insert(structure(k)).second) unique.push_back(k);
      keep = std::move(unique);
    }
    if (keep.size() == 1) return keep[0];
    int start = static_cast<int>(pool_.ckids.size());
    pool_.ckids.insert(pool_.ckids.end(), keep.begin(), keep.end());
    return add_c({is_and ? CNode::And : CNode::Or, start, static_cast<int>(keep.size())});
  }

  struct NumResult {
    int node = -1;     // numeric node, or -1 when the value is a matrix
    int matrix = -1;   // static matrix index
  };

  NumResult num(const NumExpr& x, std::vector<ObjectId>& b) {
    using K = NumExpr::Kind;
    auto bin = [&](NNode::Op op) -> NumResult {
      int l = num_int(x.kids[0], b), r = num_int(x.kids[1], b);
      // fluent +/- constant (and constant + fluent) stay a single fluent node
      // (while the offset is small: fluents are 16-bit, see Task::kMaxFluent)
      auto small_offset = [](int64_t off, int64_t k) { return std::abs(off) < (1 << 20) && std::abs(k) < (1 << 20); };
      if ((op == NNode::Add || op == NNode::Sub) && pool_.nnodes[l].op == NNode::Fluent && is_const_n(r) &&
          small_offset(pool_.nnodes[l].a, pool_.nnodes[r].v)) {
        NNode f = pool_.nnodes[l];
        f.a += static_cast<int>(op == NNode::Add ? pool_.nnodes[r].v : -pool_.nnodes[r].v);
        return {add_n(f), -1};
      }
      if (op == NNode::Add && is_const_n(l) && pool_.nnodes[r].op == NNode::Fluent &&
          small_offset(pool_.nnodes[r].a, pool_.nnodes[l].v)) {
        NNode f = pool_.nnodes[r];
        f.a += static_cast<int>(pool_.nnodes[l].v);
        return {add_n(f), -1};
      }
      if (is_const_n(l) && is_const_n(r)) {
        int64_t a = pool_.nnodes[l].v, c = pool_.nnodes[r].v;
        if (op == NNode::Div && c == 0) throw InputError(x.loc, "division by zero");
        int64_t v = checked(op == NNode::Add ? '+' : op == NNode::Sub ? '-' : op == NNode::Mul ? '*' : '/', a, c, x.loc);
        return {add_n({NNode::Const, v, 0, 0}), -1};
      }
      if (op == NNode::Div) {  // where it was written, for a divisor that is 0 in some state
        pool_.div_locs.push_back(x.loc);
        return {add_n({op, static_cast<int64_t>(pool_.div_locs.size() - 1), l, r}), -1};
      }
      return {add_n({op, 0, l, r}), -1};
    };
    switch (x.kind) {
      case K::Const: return {add_n({NNode::Const, x.value, 0, 0}), -1};
      case K::Fluent: {
        std::vector<ObjectId> args;
        for (auto& a : x.args) args.push_back(resolve(a, b));
        if (!args_fit(d_.functions[x.func].arg_types, args))
          throw InputError(x.loc, "fluent '" + printable(d_.functions[x.func].name) + "' applied to an object of the wrong type");
        if (int slot = fluent_slot(x.func, args); slot >= 0) return {add_n({NNode::Fluent, slot, 0, 0}), -1};
        auto k = key_of(x.func, args);
        if (auto m = ct_.static_matrix_.find(k); m != ct_.static_matrix_.end()) return {-1, m->second};
        auto it = ct_.static_int_.find(k);
        if (it == ct_.static_int_.end()) {
          std::string f = "(" + d_.functions[x.func].name;
          for (ObjectId o : args) f += " " + p_.objects[static_cast<size_t>(o)].name;
          throw InputError(x.loc, printable("fluent " + f + ") has no value in the initial state, and a reachable "
                                            "action or the condition reads it"));
        }
        return {add_n({NNode::Const, it->second, 0, 0}), -1};
      }
      case K::Object: throw InputError(x.loc, "an object is not a numeric value");
      case K::Add: return bin(NNode::Add);
      case K::Sub: return bin(NNode::Sub);
      case K::Mul: return bin(NNode::Mul);
      case K::Div: return bin(NNode::Div);
      case K::Neg: {
        int a = num_int(x.kids[0], b);
        if (is_const_n(a)) return {add_n({NNode::Const, checked('-', 0, pool_.nnodes[a].v, x.loc), 0, 0}), -1};
        return {add_n({NNode::Neg, 0, a, 0}), -1};
      }
      case K::GetIndex: {
        NumResult m = num(x.kids[0], b);
        if (m.matrix < 0) throw InputError(x.kids[0].loc, "get-index expects a static bit-matrix");
        int r = num_int(x.kids[1], b), c = num_int(x.kids[2], b);
        if (is_const_n(r) && is_const_n(c)) {
          const BitMatrix& mx = ct_.matrices_[m.matrix];
          int64_t rv = pool_.nnodes[r].v, cv = pool_.nnodes[c].v;
          int64_t v = (rv < 1 || rv > mx.rows || cv < 1 || cv > mx.cols) ? -1 : mx.get(int(rv - 1), int(cv - 1));
          return {add_n({NNode::Const, v, 0, 0}), -1};
        }
        return {add_n({NNode::GetIndex, m.matrix, r, c}), -1};
      }
      case K::Width: case K::Height: {
        NumResult m = num(x.kids[0], b);
        if (m.matrix < 0) throw InputError(x.kids[0].loc, "width/height expects a static bit-matrix");
        const BitMatrix& mx = ct_.matrices_[m.matrix];
        return {add_n({NNode::Const, x.kind == K::Width ? mx.cols : mx.rows, 0, 0}), -1};
      }
      case K::NewMatrix: case K::SetIndex:
        throw InputError(x.loc, "bit-matrix construction is only allowed in :init");
    }
    return {};
  }
  int num_int(const NumExpr& x, std::vector<ObjectId>& b) {
    NumResult r = num(x, b);
    if (r.node < 0) throw InputError(x.loc, "expected a number, found a bit-matrix");
    return r.node;
  }

  // f() for every binding of a quantifier's variables, until f returns
  // false. Every binding counts against the expansion budget of the
  // condition or action being compiled (GroundingOptions::max_ground_actions):
  // nested quantifiers over many objects are refused at once, not after
  // minutes and all the memory.
  template <class F>
  void for_each_binding(const std::vector<TypeId>& types, int first, std::vector<ObjectId>& b, const SourceLoc& loc,
                        F&& f) {
    if (b.size() < first + types.size()) b.resize(first + types.size(), -1);
    for_each_tuple(types, [&](const std::vector<ObjectId>& tuple) {
      if (++expansions_ > ct_.opts_.max_ground_actions)
        throw InputError(loc, "expanding this quantifier (with those around it) takes more than " +
                                  std::to_string(ct_.opts_.max_ground_actions) +
                                  " instances, the limit of ground actions (--max-ground-actions): quantify over fewer "
                                  "objects or nest fewer quantifiers");
      for (size_t i = 0; i < tuple.size(); ++i) b[first + i] = tuple[i];
      return f();
    });
  }

 public:
  // Starts the expansion budget of one condition or action.
  void reset_expansions() { expansions_ = 0; }

 protected:
  int64_t expansions_ = 0;
  bool in_quantifier_ = false;
  std::vector<int64_t> type_size_;  // objects per type (-1: not counted yet)

  // How many quantifier instances expanding `c` takes when nothing decides
  // it early: each quantifier's bindings times (1 + its body's), summed
  // over junctions (saturating).
  int64_t instances(const Condition& c) {
    using K = Condition::Kind;
    auto add = [](int64_t x, int64_t y) {
      int64_t v = 0;
      return __builtin_add_overflow(x, y, &v) ? std::numeric_limits<int64_t>::max() : v;
    };
    int64_t n = 0;
    for (const Condition& k : c.kids) n = add(n, instances(k));
    if (c.kind != K::Exists && c.kind != K::Forall) return n;
    int64_t bindings = 1;
    for (TypeId t : c.var_types) {
      if (type_size_.size() <= static_cast<size_t>(t)) type_size_.resize(static_cast<size_t>(t) + 1, -1);
      if (type_size_[static_cast<size_t>(t)] < 0) type_size_[static_cast<size_t>(t)] = static_cast<int64_t>(objects_of(t).size());
      int64_t v = 0;
      bindings = __builtin_mul_overflow(bindings, type_size_[static_cast<size_t>(t)], &v) ? std::numeric_limits<int64_t>::max() : v;
    }
    int64_t v = 0;
    return __builtin_mul_overflow(bindings, add(n, 1), &v) ? std::numeric_limits<int64_t>::max() : v;
  }

 public:

  int cond(const Condition& c, std::vector<ObjectId>& b) {
    using K = Condition::Kind;
    switch (c.kind) {
      case K::True: return Task::kTrue;
      case K::False: return Task::kFalse;
      case K::Atom: {
        std::vector<ObjectId> args;
        for (auto& a : c.args) args.push_back(resolve(a, b));
        if (!args_fit(d_.predicates[c.pred].arg_types, args)) return Task::kFalse;
        if (int bit = atom_bit(c.pred, args); bit >= 0) return add_c({CNode::Atom, bit, 0});
        return ct_.static_true_.count(key_of(c.pred, args)) ? Task::kTrue : Task::kFalse;
      }
      case K::Not: return negate(cond(c.kids[0], b));
      case K::And: case K::Or: {
        std::vector<int> kids;
        for (auto& k : c.kids) {
          int x = cond(k, b);
          kids.push_back(x);
          if (x == (c.kind == K::And ? Task::kFalse : Task::kTrue)) break;  // short-circuit grounding
        }
        return junction(c.kind == K::And, kids);
      }
      case K::Imply: return junction(false, {negate(cond(c.kids[0], b)), cond(c.kids[1], b)});
      case K::Exists: case K::Forall: {
        // The outermost quantifier first weighs the whole nest: one beyond
        // the budget is refused before any of it is expanded.
        if (!in_quantifier_) {
          const int64_t need = instances(c);
          if (need > ct_.opts_.max_ground_actions - expansions_)
            throw InputError(c.loc, "expanding this quantifier (with those nested in it) takes " + std::to_string(need) +
                                        " instances, more than the limit of " +
                                        std::to_string(ct_.opts_.max_ground_actions) +
                                        " (--max-ground-actions): quantify over fewer objects or nest fewer quantifiers");
        }
        const bool outer = !in_quantifier_;
        in_quantifier_ = true;
        std::vector<int> kids;
        bool is_and = c.kind == K::Forall;
        try {
          for_each_binding(c.var_types, c.first_var, b, c.loc, [&] {
            int x = cond(c.kids[0], b);
            kids.push_back(x);
            return x != (is_and ? Task::kFalse : Task::kTrue);  // decided: stop
          });
        } catch (...) {
          if (outer) in_quantifier_ = false;
          throw;
        }
        if (outer) in_quantifier_ = false;
        return junction(is_and, kids);
      }
      default: break;
    }
    // comparisons
    const NumExpr& l = c.nums[0];
    const NumExpr& r = c.nums[1];
    if (l.kind == NumExpr::Kind::Object || r.kind == NumExpr::Kind::Object) {
      bool eq = resolve(l.args[0], b) == resolve(r.args[0], b);
      return eq ? Task::kTrue : Task::kFalse;
    }
    int a = num_int(l, b), z = num_int(r, b);
    CNode::Op op = c.kind == K::Equal ? CNode::Eq : c.kind == K::Less ? CNode::Lt : c.kind == K::LessEq ? CNode::Le
                   : c.kind == K::Greater ? CNode::Gt : CNode::Ge;
    if (is_const_n(a) && is_const_n(z)) {
      int64_t x = pool_.nnodes[a].v, y = pool_.nnodes[z].v;
      bool v = op == CNode::Eq ? x == y : op == CNode::Lt ? x < y : op == CNode::Le ? x <= y : op == CNode::Gt ? x > y : x >= y;
      return v ? Task::kTrue : Task::kFalse;
    }
    // Fast paths. Comparison codes: Eq 0, Ne 1, Lt 2, Le 3, Gt 4, Ge 5.
    auto code = [](CNode::Op o) { return o == CNode::Eq ? 0 : o == CNode::Lt ? 2 : o == CNode::Le ? 3 : o == CNode::Gt ? 4 : 5; };
    static const int mirror[6] = {0, 1, 4, 5, 2, 3};  // x < y  <=>  y > x
    const NNode& na = pool_.nnodes[a];
    const NNode& nz = pool_.nnodes[z];
    auto small = [](int64_t v) { return v > -(1 << 27) && v < (1 << 27); };
    // A state's fluent is 16-bit (Task::kMinFluent..kMaxFluent): against a
    // constant beyond that, the comparison holds in every state (folded to
    // true) or needs a value no state holds (an input error, not a silent
    // "never").
    auto beyond = [&](const NNode& f, int64_t k, int cmp) -> int {
      int64_t want = 0;
      if (__builtin_sub_overflow(k, static_cast<int64_t>(f.a), &want))
        want = k > 0 ? std::numeric_limits<int64_t>::max() : std::numeric_limits<int64_t>::min();
      if (want >= Task::kMinFluent - 1 && want <= Task::kMaxFluent + 1) return -1;
      if (detail::compare(Task::kMinFluent, cmp, want) && detail::compare(Task::kMaxFluent, cmp, want)) return Task::kTrue;
      throw InputError(c.loc, printable("this comparison of fluent " + ct_.fluent_str(static_cast<int>(f.v)) +
                                        " with " + std::to_string(k) +
                                        " asks for a value beyond what states hold: the numeric fluents actions "
                                        "change are 16-bit integers (" +
                                        std::to_string(Task::kMinFluent) + ".." + std::to_string(Task::kMaxFluent) + ")"));
    };
    if (na.op == NNode::Fluent && is_const_n(z))
      if (int v = beyond(na, nz.v, code(op)); v >= 0) return v;
    if (nz.op == NNode::Fluent && is_const_n(a))
      if (int v = beyond(nz, na.v, mirror[code(op)]); v >= 0) return v;
    if (na.op == NNode::Fluent && is_const_n(z) && small(nz.v - na.a))  // slot + ka  op  c
      return add_c({CNode::SlotConst, static_cast<int>(na.v), static_cast<int>(nz.v - na.a), code(op)});
    if (nz.op == NNode::Fluent && is_const_n(a) && small(na.v - nz.a))  // c  op  slot + kz
      return add_c({CNode::SlotConst, static_cast<int>(nz.v), static_cast<int>(na.v - nz.a), mirror[code(op)]});
    if (na.op == NNode::Fluent && nz.op == NNode::Fluent)  // slot_a + ka  op  slot_z + kz
      return add_c({CNode::SlotSlot, static_cast<int>(na.v), static_cast<int>(nz.v), code(op) | ((nz.a - na.a) << 3)});
    return add_c({op, a, z});
  }

 protected:
  const Task& ct_;
  const Domain& d_;
  const Problem& p_;
  Task::Pool& pool_;
};

// Builds a Task. Pass 1 discovers which ground atoms/fluents any action can
// change; pass 2 compiles everything with the rest folded as static.
class Grounder : public ConditionCompiler {
 public:
  explicit Grounder(Task& t) : ConditionCompiler(t, t.pool_), t_(t) {
    if (t.opts_.check_memory)
      if (auto h = util::memory_headroom()) headroom_ = *h;
  }

  void run() {
    eval_init();
    find_dynamic_symbols();
    explore();
    // Pass 1: provisional bits for every reachable atom of a changeable predicate.
    pass_ = 1;
    reset_tables();
    ground_actions();
    std::set<std::vector<int>> mod_atoms, mod_fluents;
    for (auto& a : t_.actions_) collect_modified(a, mod_atoms, mod_fluents);
    // Pass 2: only what some action changes (or the caller asked for) is dynamic.
    pass_ = 2;
    modified_atoms_ = std::move(mod_atoms);
    modified_fluents_ = std::move(mod_fluents);
    reset_tables();
    for (auto& name : t_.opts_.keep_dynamic) {
      auto pid = d_.find_predicate(name);
      if (!pid) continue;  // a domain without that predicate
      for_each_tuple(d_.predicates[*pid].arg_types, [&](const std::vector<ObjectId>& args) {
        intern_atom(*pid, args);
        return true;
      });
    }
    // Derived atoms: a bit for every reachable one, before anything reads them.
    for (int id = 0; id < reach_.atoms.size(); ++id) {
      const int pred = reach_.atoms.pred(id);
      if (pred < static_cast<int>(d_.predicates.size()) && d_.predicates[static_cast<size_t>(pred)].derived)
        intern_atom(pred, std::vector<ObjectId>(reach_.atoms.args(id), reach_.atoms.args(id) + reach_.atoms.arity(id)));
    }
    ground_actions();
    ground_axioms();
    finish_layout();
  }

 private:
  // ------------------------------------------------------------ init values
  InitValue eval_init_num(const NumExpr& x) {
    using K = NumExpr::Kind;
    auto kid_int = [&](int i) {
      InitValue v = eval_init_num(x.kids[i]);
      if (v.is_matrix) throw InputError(x.kids[i].loc, "expected a number, found a bit-matrix");
      return v.i;
    };
    InitValue out;
    switch (x.kind) {
      case K::Const: out.i = x.value; return out;
      case K::Fluent: {
        std::vector<ObjectId> args;
        for (auto& a : x.args) args.push_back(a.index);
        auto it = init_.find(key_of(x.func, args));
        if (it == init_.end())
          throw InputError(x.loc, "fluent '" + printable(d_.functions[x.func].name) + "' is read before it is assigned");
        return it->second;
      }
      case K::Object: throw InputError(x.loc, "an object is not a numeric value");
      case K::Add: out.i = checked('+', kid_int(0), kid_int(1), x.loc); return out;
      case K::Sub: out.i = checked('-', kid_int(0), kid_int(1), x.loc); return out;
      case K::Mul: out.i = checked('*', kid_int(0), kid_int(1), x.loc); return out;
      case K::Div: {
        int64_t b = kid_int(1);
        if (b == 0) throw InputError(x.loc, "division by zero");
        out.i = checked('/', kid_int(0), b, x.loc);
        return out;
      }
      case K::Neg: out.i = checked('-', 0, kid_int(0), x.loc); return out;
      case K::NewMatrix: {
        bool fill = kid_int(0) != 0;
        int64_t r = kid_int(1), c = kid_int(2);
        if (r <= 0 || c <= 0 || r * c > 1'000'000) throw InputError(x.loc, "bad bit-matrix size");
        out.is_matrix = true;
        out.m.rows = static_cast<int>(r);
        out.m.cols = static_cast<int>(c);
        out.m.cells.assign(static_cast<size_t>(r * c), fill ? 1 : 0);
        return out;
      }
      case K::SetIndex: {
        InitValue m = eval_init_num(x.kids[0]);
        if (!m.is_matrix) throw InputError(x.kids[0].loc, "set-index expects a bit-matrix");
        bool v = kid_int(1) != 0;
        int64_t r = kid_int(2), c = kid_int(3);
        if (r < 1 || r > m.m.rows || c < 1 || c > m.m.cols)
          throw InputError(x.loc, "set-index out of range: (" + std::to_string(r) + ", " + std::to_string(c) +
                                      ") in a " + std::to_string(m.m.rows) + "x" + std::to_string(m.m.cols) + " matrix");
        m.m.cells[static_cast<size_t>((r - 1) * m.m.cols + (c - 1))] = v;
        return m;
      }
      case K::GetIndex: {
        InitValue m = eval_init_num(x.kids[0]);
        if (!m.is_matrix) throw InputError(x.kids[0].loc, "get-index expects a bit-matrix");
        int64_t r = kid_int(1), c = kid_int(2);
        if (r < 1 || r > m.m.rows || c < 1 || c > m.m.cols) throw InputError(x.loc, "get-index out of range");
        out.i = m.m.get(static_cast<int>(r - 1), static_cast<int>(c - 1));
        return out;
      }
      case K::Width: case K::Height: {
        InitValue m = eval_init_num(x.kids[0]);
        if (!m.is_matrix) throw InputError(x.kids[0].loc, "width/height expects a bit-matrix");
        out.i = x.kind == K::Width ? m.m.cols : m.m.rows;
        return out;
      }
    }
    return out;
  }

  void eval_init() {
    for (auto& a : p_.init_atoms) t_.static_true_.insert(key_of(a.pred, a.args));
    for (auto& f : p_.init_fluents) {
      InitValue v = eval_init_num(f.value);
      bool want_matrix = d_.functions[f.func].type == ValueType::Matrix;
      if (v.is_matrix != want_matrix)
        throw InputError(f.loc, "fluent '" + printable(d_.functions[f.func].name) + "' expects " +
                                    (want_matrix ? "a bit-matrix" : "a number"));
      init_[key_of(f.func, f.args)] = std::move(v);
      init_locs_[key_of(f.func, f.args)] = f.value.loc;
    }
    for (auto& [k, v] : init_) {
      if (v.is_matrix) {
        t_.static_matrix_[k] = static_cast<int>(t_.matrices_.size());
        t_.matrices_.push_back(v.m);
      } else {
        t_.static_int_[k] = v.i;
      }
    }
  }

  void effect_symbols(const Effect& e) {
    switch (e.kind) {
      case Effect::Kind::Add: case Effect::Kind::Del: t_.dynamic_preds_.insert(e.pred); break;
      case Effect::Kind::Assign: case Effect::Kind::Increase: case Effect::Kind::Decrease:
      case Effect::Kind::ScaleUp: case Effect::Kind::ScaleDown:
        if (d_.total_cost && e.func == *d_.total_cost) break;
        if (d_.functions[e.func].type == ValueType::Matrix)
          throw InputError(e.loc, "actions may not change bit-matrix fluents (unsupported)");
        t_.dynamic_funcs_.insert(e.func);
        break;
      default: break;
    }
    for (auto& k : e.kids) effect_symbols(k);
  }

  void find_dynamic_symbols() {
    for (auto& a : d_.actions) effect_symbols(a.effect);
    for (auto& n : t_.opts_.keep_dynamic)
      if (auto pid = d_.find_predicate(n)) t_.dynamic_preds_.insert(*pid);
  }

  void reset_tables() {
    t_.atoms_.clear();
    t_.fluents_.clear();
    t_.atom_index_.clear();
    t_.fluent_index_.clear();
    t_.actions_.clear();
    t_.action_index_.clear();
    pool_.cnodes.clear();
    pool_.ckids.clear();
    pool_.nnodes.clear();
    pool_.cnodes.push_back({Task::CNode::True, 0, 0});
    pool_.cnodes.push_back({Task::CNode::False, 0, 0});
  }

  // ------------------------------------------------------------ atoms & fluents
  int intern_atom(PredId pred, const std::vector<ObjectId>& args) {
    auto k = key_of(pred, args);
    auto it = t_.atom_index_.find(k);
    if (it != t_.atom_index_.end()) return it->second;
    int bit = static_cast<int>(t_.atoms_.size());
    t_.atoms_.push_back({pred, args});
    t_.atom_index_.emplace(std::move(k), bit);
    return bit;
  }
  int intern_fluent(FuncId f, const std::vector<ObjectId>& args) {
    auto k = key_of(f, args);
    auto it = t_.fluent_index_.find(k);
    if (it != t_.fluent_index_.end()) return it->second;
    int slot = static_cast<int>(t_.fluents_.size());
    t_.fluents_.push_back({f, args});
    t_.fluent_index_.emplace(std::move(k), slot);
    return slot;
  }

  // Is this ground atom part of the state? (else it is folded: false when
  // unreachable, its initial value when nothing changes it)
  bool atom_is_dynamic(PredId pred, const std::vector<ObjectId>& args) const {
    if (d_.predicates[static_cast<size_t>(pred)].derived) return reach_.reached(pred, args);
    if (!t_.dynamic_preds_.count(pred)) return false;
    if (t_.opts_.keep_dynamic.count(d_.predicates[pred].name)) return true;
    if (pass_ == 1) return reach_.reached(pred, args);
    return modified_atoms_.count(key_of(pred, args)) > 0;
  }
  bool fluent_is_dynamic(FuncId f, const std::vector<ObjectId>& args) const {
    if (!t_.dynamic_funcs_.count(f)) return false;
    if (pass_ == 1) return true;
    return modified_fluents_.count(key_of(f, args)) > 0;
  }

  int atom_bit(PredId pred, const std::vector<ObjectId>& args) override {
    return atom_is_dynamic(pred, args) ? intern_atom(pred, args) : -1;
  }
  int fluent_slot(FuncId f, const std::vector<ObjectId>& args) override {
    return fluent_is_dynamic(f, args) ? intern_fluent(f, args) : -1;
  }

  void effect(const Effect& e, std::vector<ObjectId>& b, int ctx, GroundAction& ga) {
    using K = Effect::Kind;
    auto target = [&]() -> EffectList& {
      if (ctx == Task::kTrue) return ga.eff;
      for (auto& ce : ga.cond_eff)
        if (ce.cond == ctx) return ce.eff;
      ga.cond_eff.push_back({ctx, {}});
      return ga.cond_eff.back().eff;
    };
    switch (e.kind) {
      case K::And:
        for (auto& k : e.kids) effect(k, b, ctx, ga);
        return;
      case K::Add: case K::Del: {
        std::vector<ObjectId> args;
        for (auto& a : e.args) args.push_back(resolve(a, b));
        if (!args_fit(d_.predicates[e.pred].arg_types, args)) return;
        int bit = atom_bit(e.pred, args);
        if (bit < 0) return;  // pruned in pass 2: nothing can change it
        (e.kind == K::Add ? target().add : target().del).push_back(bit);
        return;
      }
      case K::When: {
        int c = junction(true, {ctx, cond(e.cond, b)});
        if (c == Task::kFalse) return;
        effect(e.kids[0], b, c, ga);
        return;
      }
      case K::Forall:
        for_each_binding(e.var_types, e.first_var, b, e.loc, [&] {
          effect(e.kids[0], b, ctx, ga);
          return true;
        });
        return;
      default: break;
    }
    // numeric
    if (d_.total_cost && e.func == *d_.total_cost) {
      int v = num_int(e.value, b);
      if (!is_const_n(v) || e.kind != K::Increase || ctx != Task::kTrue)
        throw InputError(e.loc, "only (increase (total-cost) <constant>) is supported for action costs");
      const int64_t c = pool_.nnodes[v].v;
      if (c < 0)
        throw InputError(e.loc, printable("action " + action_str(ga) + " has a negative cost (" + std::to_string(c) +
                                          "): action costs must be non-negative"));
      if (!p_.metric) ga.cost += static_cast<double>(c);
      else add_metric_cost(e, {}, c, ga);
      return;
    }
    std::vector<ObjectId> args;
    for (auto& a : e.args) args.push_back(resolve(a, b));
    if (!args_fit(d_.functions[e.func].arg_types, args)) return;
    if (p_.metric) metric_effect(e, args, b, ctx, ga);
    int slot = fluent_slot(e.func, args);
    if (slot < 0) return;
    NumericEffect ne;
    ne.op = e.kind == K::Assign ? NumericEffect::Op::Assign : e.kind == K::Increase ? NumericEffect::Op::Increase
            : e.kind == K::Decrease ? NumericEffect::Op::Decrease : e.kind == K::ScaleUp ? NumericEffect::Op::ScaleUp
                                    : NumericEffect::Op::ScaleDown;
    ne.slot = slot;
    ne.expr = num_int(e.value, b);
    target().num.push_back(ne);
  }

  // ------------------------------------------------------------ derived predicates
  // Strata of the derived predicates: a rule's predicate sits at least as
  // high as those its condition reads positively, and above those it reads
  // negatively (under a not, or as an imply's premise). A cycle through a
  // negation has no strata: refused.
  std::vector<int> derived_strata() const {
    struct Edge {
      PredId from, to;
      bool negative;
      SourceLoc loc;
    };
    std::vector<Edge> edges;
    std::function<void(const Condition&, PredId, bool, const SourceLoc&)> walk =
        [&](const Condition& c, PredId head, bool neg, const SourceLoc& loc) {
          using K = Condition::Kind;
          if (c.kind == K::Atom && d_.predicates[static_cast<size_t>(c.pred)].derived) edges.push_back({head, c.pred, neg, loc});
          for (size_t i = 0; i < c.kids.size(); ++i)
            walk(c.kids[i], head, c.kind == K::Not || (c.kind == K::Imply && i == 0) ? !neg : neg, loc);
        };
    for (const DerivedRule& r : d_.derived) walk(r.body, r.pred, false, r.loc);
    std::vector<int> stratum(d_.predicates.size(), 0);
    const int limit = static_cast<int>(d_.predicates.size());
    for (bool changed = true; changed;) {
      changed = false;
      for (const Edge& e : edges) {
        const int need = stratum[static_cast<size_t>(e.to)] + (e.negative ? 1 : 0);
        if (stratum[static_cast<size_t>(e.from)] >= need) continue;
        if (need > limit)
          throw InputError(e.loc, printable("derived predicate '" + d_.predicates[static_cast<size_t>(e.from)].name +
                                            "' depends on the negation of itself (through '" +
                                            d_.predicates[static_cast<size_t>(e.to)].name +
                                            "'): derived predicates must be stratified"));
        stratum[static_cast<size_t>(e.from)] = need;
        changed = true;
      }
    }
    return stratum;
  }

  // A ground rule for every reachable derived atom and every rule of its
  // predicate, by stratum.
  void ground_axioms() {
    if (d_.derived.empty()) return;
    const std::vector<int> stratum = derived_strata();
    std::vector<std::vector<int>> atoms_of(d_.predicates.size());
    for (int id = 0; id < reach_.atoms.size(); ++id)
      if (reach_.atoms.pred(id) < static_cast<int>(d_.predicates.size())) atoms_of[static_cast<size_t>(reach_.atoms.pred(id))].push_back(id);
    std::vector<std::pair<int, Axiom>> made;
    std::vector<ObjectId> args;
    for (const DerivedRule& r : d_.derived) {
      for (int id : atoms_of[static_cast<size_t>(r.pred)]) {
        args.assign(reach_.atoms.args(id), reach_.atoms.args(id) + reach_.atoms.arity(id));
        if (!args_fit(r.param_types, args)) continue;
        std::vector<ObjectId> b(std::max<size_t>(static_cast<size_t>(r.num_vars), args.size()), -1);
        std::copy(args.begin(), args.end(), b.begin());
        reset_expansions();
        const int body = cond(r.body, b);
        if (body == Task::kFalse) continue;
        made.push_back({stratum[static_cast<size_t>(r.pred)], Axiom{intern_atom(r.pred, args), body}});
      }
    }
    std::stable_sort(made.begin(), made.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    t_.axioms_.clear();
    t_.stratum_begin_.clear();
    for (size_t i = 0; i < made.size(); ++i) {
      if (i == 0 || made[i].first != made[i - 1].first) t_.stratum_begin_.push_back(static_cast<int>(i));
      t_.axioms_.push_back(made[i].second);
    }
    t_.stratum_begin_.push_back(static_cast<int>(made.size()));
  }

  std::string action_str(const GroundAction& ga) const {
    std::string name = "(" + d_.actions[static_cast<size_t>(ga.schema)].name;
    for (ObjectId o : ga.args) name += " " + p_.objects[static_cast<size_t>(o)].name;
    return name + ")";
  }

  // The :metric's share of an effect that changes fluent (func args) by
  // `delta`: coef x delta for each of the metric's terms on that fluent.
  void add_metric_cost(const Effect& e, const std::vector<ObjectId>& args, int64_t delta, GroundAction& ga) {
    for (const Metric::Term& t : p_.metric->terms)
      if (t.func == e.func && t.args == args) ga.cost += static_cast<double>(t.coef) * static_cast<double>(delta);
  }

  // An effect on a fluent the metric reads: it must change it by a constant,
  // unconditionally, so that every action has one cost.
  void metric_effect(const Effect& e, const std::vector<ObjectId>& args, std::vector<ObjectId>& b, int ctx,
                     GroundAction& ga) {
    bool read = false;
    for (const Metric::Term& t : p_.metric->terms) read |= t.func == e.func && t.args == args;
    if (!read) return;
    const std::string fluent = fluent_text(e.func, args);
    const int v = num_int(e.value, b);
    if ((e.kind != Effect::Kind::Increase && e.kind != Effect::Kind::Decrease) || !is_const_n(v) || ctx != Task::kTrue)
      throw InputError(e.loc, printable("the :metric (" + p_.file + ":" + std::to_string(p_.metric->loc.line) +
                                        ") reads " + fluent + ", which action " + action_str(ga) +
                                        " changes other than by an unconditional (increase/decrease " + fluent +
                                        " <constant>): only such metrics, whose actions each have one cost, are supported"));
    const int64_t c = pool_.nnodes[static_cast<size_t>(v)].v;
    add_metric_cost(e, args, e.kind == Effect::Kind::Increase ? c : -c, ga);
  }

  std::string fluent_text(FuncId f, const std::vector<ObjectId>& args) const {
    std::string s = "(" + d_.functions[static_cast<size_t>(f)].name;
    for (ObjectId o : args) s += " " + p_.objects[static_cast<size_t>(o)].name;
    return s + ")";
  }

  void ground_actions() {
    std::vector<int> order;
    if (!t_.opts_.schema_order.empty()) {
      for (auto& n : t_.opts_.schema_order) {
        int i = d_.find_action(n);
        if (i >= 0) order.push_back(i);
      }
      for (int i = 0; i < static_cast<int>(d_.actions.size()); ++i)
        if (std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
    } else {
      for (int i = 0; i < static_cast<int>(d_.actions.size()); ++i) order.push_back(i);
    }
    uint64_t visited = 0;
    std::vector<ObjectId> args;
    for (int si : order) {
      const ActionSchema& s = d_.actions[si];
      const size_t n = s.param_types.size();
      schema_ = si;
      const std::vector<ObjectId>& flat = reach_.tuples[static_cast<size_t>(si)];
      for (size_t k : tuple_order(si)) {
        args.assign(flat.begin() + static_cast<std::ptrdiff_t>(k * n), flat.begin() + static_cast<std::ptrdiff_t>(k * n + n));
        ground_one(si, args);
        if (++visited % kTupleCheckInterval == 0) on_tuples(visited);
      }
      schema_ = -1;
    }
  }

  // The reachable tuples of schema `si` in the order an enumeration of its
  // parameters' objects meets them (the last parameter fastest, or the first
  // with GroundingOptions::first_param_fastest): action ids do not depend on
  // the order reachability found them.
  std::vector<size_t> tuple_order(int si) const {
    const ActionSchema& s = d_.actions[static_cast<size_t>(si)];
    const size_t n = s.param_types.size();
    const std::vector<ObjectId>& flat = reach_.tuples[static_cast<size_t>(si)];
    const size_t count = static_cast<size_t>(reach_.counts[static_cast<size_t>(si)]);
    std::vector<std::vector<int>> rank(n, std::vector<int>(p_.objects.size(), 0));
    for (size_t i = 0; i < n; ++i) {
      const auto objs = objects_of(s.param_types[i]);
      for (size_t r = 0; r < objs.size(); ++r) rank[i][static_cast<size_t>(objs[r])] = static_cast<int>(r);
    }
    std::vector<size_t> order(count);
    for (size_t k = 0; k < count; ++k) order[k] = k;
    const bool first_fastest = t_.opts_.first_param_fastest;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      for (size_t j = 0; j < n; ++j) {
        const size_t i = first_fastest ? n - 1 - j : j;
        const int ra = rank[i][static_cast<size_t>(flat[a * n + i])], rb = rank[i][static_cast<size_t>(flat[b * n + i])];
        if (ra != rb) return ra < rb;
      }
      return false;
    });
    return order;
  }

  // Reachability first: only the actions and atoms it finds are grounded
  // (reachability.hpp), and the size limit counts those.
  void explore() {
    std::set<PredId> keep_all;
    for (const auto& name : t_.opts_.keep_dynamic)
      if (auto pid = d_.find_predicate(name)) keep_all.insert(*pid);
    ReachabilityLimits lim;
    lim.max_actions = t_.opts_.max_ground_actions;
    lim.deadline = t_.opts_.deadline;
    lim.deadline_label = t_.opts_.deadline_label;
    lim.check_memory = t_.opts_.check_memory;
    lim.bytes_per_action = GroundingOptions::kBytesPerGroundAction;
    reach_ = explore_reachable(d_, p_, keep_all, lim);
  }

  // The budgets, checked while grounding: the deadline, and memory (the
  // ground actions made so far must fit in the headroom the process had when
  // grounding began; reachability already checked the whole count).
  void on_tuples(uint64_t) override {
    const GroundingOptions& o = t_.opts_;
    if (o.deadline != std::chrono::steady_clock::time_point::max() && std::chrono::steady_clock::now() >= o.deadline)
      throw TimeLimitError(
                       printable(o.deadline_label + " reached while grounding" +
                                 (schema_ >= 0 ? " action '" + d_.actions[schema_].name + "'" : std::string()) + " (" +
                                 std::to_string(t_.actions_.size()) + " ground actions made so far)"));
    if (!headroom_ || schema_ < 0) return;
    const int64_t made = static_cast<int64_t>(t_.actions_.size());
    const int64_t projected = made;
    const int64_t need = saturating_mul(projected, GroundingOptions::kBytesPerGroundAction);
    if (need <= headroom_->bytes) return;
    throw MemoryLimitError(
                     printable("action '" + d_.actions[schema_].name + "' is on course to about " +
                               std::to_string(projected) + " ground actions (" + std::to_string(made) +
                               " made so far), about " + util::format_bytes(need) + ", but only " +
                               util::format_bytes(headroom_->bytes) + " is left (" + headroom_->bound +
                               "): stopped before memory ran out; lower the number of objects, or add static "
                               "preconditions that rule out parameter combinations"));
  }

  // ------------------------------------------------------------ size limits
  static int64_t saturating_mul(int64_t a, int64_t b) {
    int64_t v = 0;
    return __builtin_mul_overflow(a, b, &v) ? std::numeric_limits<int64_t>::max() : v;
  }

  void ground_one(int si, const std::vector<ObjectId>& args) {
    const ActionSchema& s = d_.actions[si];
    std::vector<ObjectId> b(std::max<size_t>(s.num_vars, args.size()), -1);
    std::copy(args.begin(), args.end(), b.begin());
    reset_expansions();
    int pre = s.precondition ? cond(*s.precondition, b) : Task::kTrue;
    if (pre == Task::kFalse) return;
    GroundAction ga;
    ga.schema = si;
    ga.args = args;
    ga.pre = pre;
    effect(s.effect, b, Task::kTrue, ga);
    if (p_.metric && ga.cost < 0)
      throw InputError(p_.metric->loc, printable("action " + action_str(ga) + " costs " + std::to_string(static_cast<int64_t>(ga.cost)) +
                                                 " under the :metric: action costs must be non-negative"));
    // trigger: the first positive atom of the precondition's top-level conjunction
    const CNode& n = pool_.cnodes[pre];
    if (n.op == CNode::Atom) ga.trigger_bit = n.a;
    else if (n.op == CNode::And)
      for (int i = 0; i < n.b; ++i)
        if (pool_.cnodes[pool_.ckids[n.a + i]].op == CNode::Atom) {
          ga.trigger_bit = pool_.cnodes[pool_.ckids[n.a + i]].a;
          break;
        }
    t_.action_index_[key_of(si, args)] = static_cast<ActionId>(t_.actions_.size());
    t_.actions_.push_back(std::move(ga));
  }

  void collect_modified(const GroundAction& a, std::set<std::vector<int>>& atoms,
                        std::set<std::vector<int>>& fluents) {
    auto list = [&](const EffectList& e) {
      for (int bit : e.add) atoms.insert(key_of(t_.atoms_[bit].first, t_.atoms_[bit].second));
      for (int bit : e.del) atoms.insert(key_of(t_.atoms_[bit].first, t_.atoms_[bit].second));
      for (auto& ne : e.num) fluents.insert(key_of(t_.fluents_[ne.slot].first, t_.fluents_[ne.slot].second));
    };
    list(a.eff);
    for (auto& ce : a.cond_eff) list(ce.eff);
  }

  // States hold fluents that actions change as int16: their initial values must fit.
  void check_state_value(int slot, int64_t v, const SourceLoc& loc) const {
    using Lim = std::numeric_limits<int16_t>;
    if (v >= Lim::min() && v <= Lim::max()) return;
    throw InputError(loc, printable("fluent " + t_.fluent_str(slot) + " value " + std::to_string(v) +
                                    " is out of range: fluents that actions change must be between " +
                                    std::to_string(Lim::min()) + " and " + std::to_string(Lim::max())));
  }

  void finish_layout() {
    t_.atom_words_ = (t_.num_atoms() + 63) / 64;
    t_.num_words_ = t_.atom_words_ + (t_.num_fluents() + 3) / 4;
    t_.init_bits_.clear();
    for (int bit = 0; bit < t_.num_atoms(); ++bit)
      if (t_.static_true_.count(key_of(t_.atoms_[bit].first, t_.atoms_[bit].second))) t_.init_bits_.push_back(bit);
    t_.init_fluent_values_.assign(t_.num_fluents(), 0);
    for (int slot = 0; slot < t_.num_fluents(); ++slot) {
      auto k = key_of(t_.fluents_[slot].first, t_.fluents_[slot].second);
      auto it = t_.static_int_.find(k);
      if (it == t_.static_int_.end()) continue;
      check_state_value(slot, it->second, init_locs_[k]);
      t_.init_fluent_values_[slot] = it->second;
    }
    std::map<int, size_t> group_of;
    for (ActionId a = 0; a < t_.num_actions(); ++a) {
      int tb = t_.actions_[a].trigger_bit;
      if (tb < 0) {
        t_.untriggered_.push_back(a);
        continue;
      }
      auto it = group_of.find(tb);
      if (it == group_of.end()) {
        group_of[tb] = t_.trigger_groups_.size();
        t_.trigger_groups_.push_back({tb, {}});
        it = group_of.find(tb);
      }
      t_.trigger_groups_[it->second].second.push_back(a);
    }
  }

  Task& t_;
  int pass_ = 1;
  std::optional<util::MemoryHeadroom> headroom_;
  int schema_ = -1;  // the schema being grounded, -1 between schemas
  std::map<std::vector<int>, InitValue> init_;
  std::map<std::vector<int>, SourceLoc> init_locs_;  // where each initial value was given
  std::set<std::vector<int>> modified_atoms_, modified_fluents_;
  Reachable reach_;
};

// ================================================================ Task

Task::Task(std::shared_ptr<const Domain> domain, std::shared_ptr<const Problem> problem,
           const GroundingOptions& opts)
    : domain_(std::move(domain)), problem_(std::move(problem)), opts_(opts) {
  Grounder g(*this);
  g.run();
  prepare_axioms();
  flatten_preconditions();
}

CompiledCondition Task::compile(const Condition& c, std::vector<ObjectId> binding) const {
  Pool pool;
  pool.cnodes = {{CNode::True, 0, 0}, {CNode::False, 0, 0}};
  ConditionCompiler compiler(*this, pool);
  CondId root = compiler.cond(c, binding);
  return CompiledCondition(*this, std::move(pool), root);
}

CompiledCondition Task::compile_text(const std::string& text, const std::string& label) const {
  int nv = 0;
  // The problem's own goal, passed back as text (e.g. when the loader skipped
  // it): parse the expression as read so errors point into the problem file.
  const auto& own = problem_->goal_sexpr;
  Condition c = own && text == own->str() ? parse_condition(*domain_, *problem_, *own, &nv)
                                          : parse_condition_text(*domain_, *problem_, text, label, &nv);
  return compile(c, std::vector<ObjectId>(nv, -1));
}

}  // namespace clips::pddl
