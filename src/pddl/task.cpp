#include "pddl/task.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "pddl/parser.hpp"

namespace clips::pddl {

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

std::vector<int> key_of(int head, const std::vector<ObjectId>& args) {
  std::vector<int> k;
  k.reserve(args.size() + 1);
  k.push_back(head);
  k.insert(k.end(), args.begin(), args.end());
  return k;
}

}  // namespace

// Builds a Task. Pass 1 discovers which ground atoms/fluents any action can
// change; pass 2 compiles everything with the rest folded as static.
class Grounder {
 public:
  Grounder(Task& t) : t_(t), d_(*t.domain_), p_(*t.problem_) {}

  void run() {
    eval_init();
    find_dynamic_symbols();
    // Pass 1: provisional bits for every atom of a changeable predicate.
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
      });
    }
    ground_actions();
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
    t_.cnodes_.clear();
    t_.ckids_.clear();
    t_.nnodes_.clear();
    t_.cnodes_.push_back({Task::CNode::True, 0, 0});
    t_.cnodes_.push_back({Task::CNode::False, 0, 0});
  }

  // ------------------------------------------------------------ objects
  std::vector<ObjectId> objects_of(TypeId t) const {
    std::vector<ObjectId> out;
    for (size_t i = 0; i < p_.objects.size(); ++i)
      if (d_.is_subtype(p_.objects[i].type, t)) out.push_back(static_cast<ObjectId>(i));
    if (t_.opts_.objects_by_name)
      std::sort(out.begin(), out.end(), [&](ObjectId a, ObjectId b) { return p_.objects[a].name < p_.objects[b].name; });
    return out;
  }

  template <class F>
  void for_each_tuple(const std::vector<TypeId>& types, F&& f, bool first_fastest = false) {
    std::vector<std::vector<ObjectId>> doms;
    for (auto t : types) {
      doms.push_back(objects_of(t));
      if (doms.back().empty()) return;
    }
    std::vector<size_t> idx(types.size(), 0);
    std::vector<ObjectId> tuple(types.size());
    for (;;) {
      for (size_t i = 0; i < types.size(); ++i) tuple[i] = doms[i][idx[i]];
      f(tuple);
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

 public:
  // Is this ground atom part of the state? (else it is folded)
  bool atom_is_dynamic(PredId pred, const std::vector<ObjectId>& args) const {
    if (!t_.dynamic_preds_.count(pred)) return false;
    if (pass_ == 1) return true;
    if (t_.opts_.keep_dynamic.count(d_.predicates[pred].name)) return true;
    return modified_atoms_.count(key_of(pred, args)) > 0;
  }
  bool fluent_is_dynamic(FuncId f, const std::vector<ObjectId>& args) const {
    if (!t_.dynamic_funcs_.count(f)) return false;
    if (pass_ == 1) return true;
    return modified_fluents_.count(key_of(f, args)) > 0;
  }

  // ------------------------------------------------------------ compilation
  using CNode = Task::CNode;
  using NNode = Task::NNode;

  int add_c(CNode n) {
    t_.cnodes_.push_back(n);
    return static_cast<int>(t_.cnodes_.size() - 1);
  }
  int add_n(NNode n) {
    t_.nnodes_.push_back(n);
    return static_cast<int>(t_.nnodes_.size() - 1);
  }
  bool is_const_n(int n) const { return t_.nnodes_[n].op == NNode::Const; }

  ObjectId resolve(const TermRef& r, const std::vector<ObjectId>& b) const {
    return r.is_var ? b[r.index] : r.index;
  }
  bool args_fit(const std::vector<TypeId>& types, const std::vector<ObjectId>& args) const {
    for (size_t i = 0; i < args.size(); ++i)
      if (!d_.is_subtype(p_.objects[args[i]].type, types[i])) return false;
    return true;
  }

  int negate(int c) {
    CNode n = t_.cnodes_[c];
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

  int junction(bool is_and, std::vector<int> kids) {
    std::vector<int> keep;
    for (int k : kids) {
      if (k == (is_and ? Task::kTrue : Task::kFalse)) continue;
      if (k == (is_and ? Task::kFalse : Task::kTrue)) return k;
      const CNode& n = t_.cnodes_[k];
      if (n.op == (is_and ? CNode::And : CNode::Or)) {  // flatten nested
        for (int i = 0; i < n.b; ++i) keep.push_back(t_.ckids_[n.a + i]);
      } else {
        keep.push_back(k);
      }
    }
    if (keep.empty()) return is_and ? Task::kTrue : Task::kFalse;
    if (keep.size() == 1) return keep[0];
    int start = static_cast<int>(t_.ckids_.size());
    t_.ckids_.insert(t_.ckids_.end(), keep.begin(), keep.end());
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
      if ((op == NNode::Add || op == NNode::Sub) && t_.nnodes_[l].op == NNode::Fluent && is_const_n(r)) {
        NNode f = t_.nnodes_[l];
        f.a += static_cast<int>(op == NNode::Add ? t_.nnodes_[r].v : -t_.nnodes_[r].v);
        return {add_n(f), -1};
      }
      if (op == NNode::Add && is_const_n(l) && t_.nnodes_[r].op == NNode::Fluent) {
        NNode f = t_.nnodes_[r];
        f.a += static_cast<int>(t_.nnodes_[l].v);
        return {add_n(f), -1};
      }
      if (is_const_n(l) && is_const_n(r)) {
        int64_t a = t_.nnodes_[l].v, c = t_.nnodes_[r].v;
        if (op == NNode::Div && c == 0) throw InputError(x.loc, "division by zero");
        int64_t v = checked(op == NNode::Add ? '+' : op == NNode::Sub ? '-' : op == NNode::Mul ? '*' : '/', a, c, x.loc);
        return {add_n({NNode::Const, v, 0, 0}), -1};
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
        if (fluent_is_dynamic(x.func, args)) return {add_n({NNode::Fluent, intern_fluent(x.func, args), 0, 0}), -1};
        auto k = key_of(x.func, args);
        if (auto m = t_.static_matrix_.find(k); m != t_.static_matrix_.end()) return {-1, m->second};
        auto it = t_.static_int_.find(k);
        if (it == t_.static_int_.end())
          throw InputError(x.loc, "fluent '" + printable(d_.functions[x.func].name) + "' has no value in the initial state");
        return {add_n({NNode::Const, it->second, 0, 0}), -1};
      }
      case K::Object: throw InputError(x.loc, "an object is not a numeric value");
      case K::Add: return bin(NNode::Add);
      case K::Sub: return bin(NNode::Sub);
      case K::Mul: return bin(NNode::Mul);
      case K::Div: return bin(NNode::Div);
      case K::Neg: {
        int a = num_int(x.kids[0], b);
        if (is_const_n(a)) return {add_n({NNode::Const, checked('-', 0, t_.nnodes_[a].v, x.loc), 0, 0}), -1};
        return {add_n({NNode::Neg, 0, a, 0}), -1};
      }
      case K::GetIndex: {
        NumResult m = num(x.kids[0], b);
        if (m.matrix < 0) throw InputError(x.kids[0].loc, "get-index expects a static bit-matrix");
        int r = num_int(x.kids[1], b), c = num_int(x.kids[2], b);
        if (is_const_n(r) && is_const_n(c)) {
          const BitMatrix& mx = t_.matrices_[m.matrix];
          int64_t rv = t_.nnodes_[r].v, cv = t_.nnodes_[c].v;
          int64_t v = (rv < 1 || rv > mx.rows || cv < 1 || cv > mx.cols) ? -1 : mx.get(int(rv - 1), int(cv - 1));
          return {add_n({NNode::Const, v, 0, 0}), -1};
        }
        return {add_n({NNode::GetIndex, m.matrix, r, c}), -1};
      }
      case K::Width: case K::Height: {
        NumResult m = num(x.kids[0], b);
        if (m.matrix < 0) throw InputError(x.kids[0].loc, "width/height expects a static bit-matrix");
        const BitMatrix& mx = t_.matrices_[m.matrix];
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

  template <class F>
  void for_each_binding(const std::vector<TypeId>& types, int first, std::vector<ObjectId>& b, F&& f) {
    if (b.size() < first + types.size()) b.resize(first + types.size(), -1);
    for_each_tuple(types, [&](const std::vector<ObjectId>& tuple) {
      for (size_t i = 0; i < tuple.size(); ++i) b[first + i] = tuple[i];
      f();
    });
  }

  int cond(const Condition& c, std::vector<ObjectId>& b) {
    using K = Condition::Kind;
    switch (c.kind) {
      case K::True: return Task::kTrue;
      case K::False: return Task::kFalse;
      case K::Atom: {
        std::vector<ObjectId> args;
        for (auto& a : c.args) args.push_back(resolve(a, b));
        if (!args_fit(d_.predicates[c.pred].arg_types, args)) return Task::kFalse;
        if (atom_is_dynamic(c.pred, args)) return add_c({CNode::Atom, intern_atom(c.pred, args), 0});
        return t_.static_true_.count(key_of(c.pred, args)) ? Task::kTrue : Task::kFalse;
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
        std::vector<int> kids;
        bool is_and = c.kind == K::Forall;
        bool decided = false;
        for_each_binding(c.var_types, c.first_var, b, [&] {
          if (decided) return;
          int x = cond(c.kids[0], b);
          if (x == (is_and ? Task::kFalse : Task::kTrue)) decided = true;
          kids.push_back(x);
        });
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
      int64_t x = t_.nnodes_[a].v, y = t_.nnodes_[z].v;
      bool v = op == CNode::Eq ? x == y : op == CNode::Lt ? x < y : op == CNode::Le ? x <= y : op == CNode::Gt ? x > y : x >= y;
      return v ? Task::kTrue : Task::kFalse;
    }
    // Fast paths. Comparison codes: Eq 0, Ne 1, Lt 2, Le 3, Gt 4, Ge 5.
    auto code = [](CNode::Op o) { return o == CNode::Eq ? 0 : o == CNode::Lt ? 2 : o == CNode::Le ? 3 : o == CNode::Gt ? 4 : 5; };
    static const int mirror[6] = {0, 1, 4, 5, 2, 3};  // x < y  <=>  y > x
    const NNode& na = t_.nnodes_[a];
    const NNode& nz = t_.nnodes_[z];
    auto small = [](int64_t v) { return v > -(1 << 27) && v < (1 << 27); };
    if (na.op == NNode::Fluent && is_const_n(z) && small(nz.v - na.a))  // slot + ka  op  c
      return add_c({CNode::SlotConst, static_cast<int>(na.v), static_cast<int>(nz.v - na.a), code(op)});
    if (nz.op == NNode::Fluent && is_const_n(a) && small(na.v - nz.a))  // c  op  slot + kz
      return add_c({CNode::SlotConst, static_cast<int>(nz.v), static_cast<int>(na.v - nz.a), mirror[code(op)]});
    if (na.op == NNode::Fluent && nz.op == NNode::Fluent)  // slot_a + ka  op  slot_z + kz
      return add_c({CNode::SlotSlot, static_cast<int>(na.v), static_cast<int>(nz.v), code(op) | ((nz.a - na.a) << 3)});
    return add_c({op, a, z});
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
        if (!atom_is_dynamic(e.pred, args)) return;  // pruned in pass 2: nothing can change it
        int bit = intern_atom(e.pred, args);
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
        for_each_binding(e.var_types, e.first_var, b, [&] { effect(e.kids[0], b, ctx, ga); });
        return;
      default: break;
    }
    // numeric
    if (d_.total_cost && e.func == *d_.total_cost) {
      int v = num_int(e.value, b);
      if (!is_const_n(v) || e.kind != K::Increase || ctx != Task::kTrue)
        throw InputError(e.loc, "only (increase (total-cost) <constant>) is supported for action costs");
      ga.cost += static_cast<double>(t_.nnodes_[v].v);
      return;
    }
    std::vector<ObjectId> args;
    for (auto& a : e.args) args.push_back(resolve(a, b));
    if (!args_fit(d_.functions[e.func].arg_types, args)) return;
    if (!fluent_is_dynamic(e.func, args)) return;
    NumericEffect ne;
    ne.op = e.kind == K::Assign ? NumericEffect::Op::Assign : e.kind == K::Increase ? NumericEffect::Op::Increase
            : e.kind == K::Decrease ? NumericEffect::Op::Decrease : e.kind == K::ScaleUp ? NumericEffect::Op::ScaleUp
                                    : NumericEffect::Op::ScaleDown;
    ne.slot = intern_fluent(e.func, args);
    ne.expr = num_int(e.value, b);
    target().num.push_back(ne);
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
    for (int si : order) {
      const ActionSchema& s = d_.actions[si];
      if (s.param_types.empty()) {
        ground_one(si, {});
        continue;
      }
      for_each_tuple(s.param_types, [&](const std::vector<ObjectId>& args) { ground_one(si, args); },
                     t_.opts_.first_param_fastest);
    }
  }

  void ground_one(int si, const std::vector<ObjectId>& args) {
    const ActionSchema& s = d_.actions[si];
    std::vector<ObjectId> b(std::max<size_t>(s.num_vars, args.size()), -1);
    std::copy(args.begin(), args.end(), b.begin());
    int pre = s.precondition ? cond(*s.precondition, b) : Task::kTrue;
    if (pre == Task::kFalse) return;
    GroundAction ga;
    ga.schema = si;
    ga.args = args;
    ga.pre = pre;
    effect(s.effect, b, Task::kTrue, ga);
    // trigger: the first positive atom of the precondition's top-level conjunction
    const CNode& n = t_.cnodes_[pre];
    if (n.op == CNode::Atom) ga.trigger_bit = n.a;
    else if (n.op == CNode::And)
      for (int i = 0; i < n.b; ++i)
        if (t_.cnodes_[t_.ckids_[n.a + i]].op == CNode::Atom) {
          ga.trigger_bit = t_.cnodes_[t_.ckids_[n.a + i]].a;
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

 private:
  Task& t_;
  const Domain& d_;
  const Problem& p_;
  int pass_ = 1;
  std::map<std::vector<int>, InitValue> init_;
  std::map<std::vector<int>, SourceLoc> init_locs_;  // where each initial value was given
  std::set<std::vector<int>> modified_atoms_, modified_fluents_;

  friend class Task;
};

// ================================================================ Task

Task::Task(std::shared_ptr<const Domain> domain, std::shared_ptr<const Problem> problem,
           const GroundingOptions& opts)
    : domain_(std::move(domain)), problem_(std::move(problem)), opts_(opts) {
  Grounder g(*this);
  g.run();
  flatten_preconditions();
}

void Task::flatten_preconditions() {
  prims_.clear();
  rests_.clear();
  prim_begin_.assign(1, 0);
  rest_begin_.assign(1, 0);
  auto primitive = [](const CNode& n) {
    return n.op == CNode::Atom || n.op == CNode::NotAtom || n.op == CNode::SlotConst || n.op == CNode::SlotSlot ||
           n.op == CNode::False;
  };
  for (const GroundAction& g : actions_) {
    const CNode& root = cnodes_[g.pre];
    std::vector<CondId> kids;
    if (root.op == CNode::And)
      for (int i = 0; i < root.b; ++i) kids.push_back(ckids_[root.a + i]);
    else if (root.op != CNode::True)
      kids.push_back(g.pre);
    for (CondId k : kids) {
      if (primitive(cnodes_[k])) prims_.push_back(cnodes_[k]);
      else rests_.push_back(k);
    }
    prim_begin_.push_back(static_cast<int>(prims_.size()));
    rest_begin_.push_back(static_cast<int>(rests_.size()));
  }
  build_chunks();
}

namespace {

// x op y for the comparison codes Eq..Ge = 0..5 (CNode::c & 7, CNode::Op - Eq).
[[gnu::always_inline]] inline bool compare(int64_t x, int op, int64_t y) {
  switch (op) {
    case 0: return x == y;
    case 1: return x != y;
    case 2: return x < y;
    case 3: return x <= y;
    case 4: return x > y;
    default: return x >= y;
  }
}

}  // namespace

void Task::build_chunks() {
  chunks_.clear();
  chunk_actions_.clear();
  lit_filters_.clear();
  gen_prims_.clear();
  gen_begin_.assign(1, 0);
  gnodes_.clear();
  gkids_.clear();
  gprims_.clear();
  cells_.clear();
  gen_rests_.clear();
  for (CondId r : rests_) gen_rests_.push_back(compile_gen(r));
  // Literal filters replace every atom test, so survivors only compare slots.
  for (ActionId a = 0; a < num_actions(); ++a) {
    for (int i = prim_begin_[a]; i < prim_begin_[a + 1]; ++i)
      if (prims_[i].op != CNode::Atom && prims_[i].op != CNode::NotAtom) gen_prims_.push_back(prims_[i]);
    gen_begin_.push_back(static_cast<int>(gen_prims_.size()));
  }
  auto add_chunks = [&](int trigger, const std::vector<ActionId>& acts) {
    for (size_t first = 0; first < acts.size(); first += 64) {
      Chunk c;
      c.trigger = trigger;
      c.first = static_cast<int>(chunk_actions_.size());
      c.count = static_cast<int>(std::min<size_t>(64, acts.size() - first));
      c.lit_begin = static_cast<int>(lit_filters_.size());
      std::map<int, LitFilter> lits;  // by bit, so filters run in bit order
      for (int j = 0; j < c.count; ++j) {
        ActionId a = acts[first + j];
        chunk_actions_.push_back(a);
        for (int i = prim_begin_[a]; i < prim_begin_[a + 1]; ++i) {
          const CNode& n = prims_[i];
          if (n.op != CNode::Atom && n.op != CNode::NotAtom) continue;
          if (n.op == CNode::Atom && n.a == trigger) continue;  // the chunk's own test
          LitFilter& f = lits[n.a];
          f.bit = n.a;
          (n.op == CNode::Atom ? f.kill_if_clear : f.kill_if_set) |= uint64_t{1} << j;
        }
      }
      for (const auto& [bit, f] : lits) lit_filters_.push_back(f);
      c.lit_end = static_cast<int>(lit_filters_.size());
      chunks_.push_back(c);
    }
  };
  for (const auto& [bit, acts] : trigger_groups_) add_chunks(bit, acts);
  add_chunks(-1, untriggered_);
}

bool Task::applicable_rest(ActionId a, const uint64_t* s) const {
  for (int i = gen_begin_[a], e = gen_begin_[a + 1]; i < e; ++i)
    if (!test_prim(gen_prims_[i], s)) return false;
  for (int i = rest_begin_[a], e = rest_begin_[a + 1]; i < e; ++i)
    if (!eval_gen(gen_rests_[i], s)) return false;
  return true;
}

int Task::compile_gen(CondId c) {
  const CNode& n = cnodes_[c];
  GNode g;
  switch (n.op) {
    case CNode::Atom: case CNode::NotAtom: case CNode::False: case CNode::SlotConst: case CNode::SlotSlot:
      g.op = GNode::Prim;
      g.prim = n;
      break;
    case CNode::And:
    case CNode::Or: {
      std::vector<int> kids;
      for (int i = 0; i < n.b; ++i) kids.push_back(compile_gen(ckids_[n.a + i]));
      if (n.op == CNode::And && std::all_of(kids.begin(), kids.end(), [&](int k) { return gnodes_[k].op == GNode::Prim; })) {
        // A conjunction of primitives: one flat loop, no recursion.
        g.op = GNode::Prims;
        g.a = static_cast<int>(gprims_.size());
        g.b = n.b;
        for (int k : kids) gprims_.push_back(gnodes_[k].prim);
        break;
      }
      g.op = n.op == CNode::And ? GNode::And : GNode::Or;
      g.a = static_cast<int>(gkids_.size());
      g.b = n.b;
      gkids_.insert(gkids_.end(), kids.begin(), kids.end());
      break;
    }
    case CNode::Not:
      g.op = GNode::Not;
      g.a = compile_gen(n.a);
      break;
    case CNode::Eq: case CNode::Ne: case CNode::Lt: case CNode::Le: case CNode::Gt: case CNode::Ge: {
      static const CNode::Op mirror[] = {CNode::Eq, CNode::Ne, CNode::Gt, CNode::Ge, CNode::Lt, CNode::Le};
      int m = n.a, k = n.b;
      CNode::Op op = n.op;
      if (nnodes_[m].op != NNode::GetIndex) {
        std::swap(m, k);
        op = mirror[op - CNode::Eq];
      }
      // coordinate: fluent (+k) or constant
      auto coord = [&](int x, int& slot, int& off) {
        const NNode& v = nnodes_[x];
        if (v.op == NNode::Const && v.v >= INT32_MIN && v.v <= INT32_MAX) return off = static_cast<int>(v.v), slot = -1, true;
        if (v.op == NNode::Fluent) return slot = static_cast<int>(v.v), off = v.a, true;
        return false;
      };
      CellTest t;
      if (nnodes_[m].op == NNode::GetIndex && nnodes_[k].op == NNode::Const &&
          coord(nnodes_[m].a, t.row_slot, t.row_k) && coord(nnodes_[m].b, t.col_slot, t.col_k)) {
        t.matrix = static_cast<int>(nnodes_[m].v);
        t.cmp = op;
        t.value = nnodes_[k].v;
        g.op = GNode::Cell;
        g.a = static_cast<int>(cells_.size());
        cells_.push_back(t);
        break;
      }
      g.op = GNode::Cond;
      g.a = c;
      break;
    }
    default:
      g.op = GNode::Cond;
      g.a = c;
  }
  gnodes_.push_back(g);
  return static_cast<int>(gnodes_.size()) - 1;
}

bool Task::eval_gen(int gi, const uint64_t* s) const {
  const GNode& g = gnodes_[gi];
  switch (g.op) {
    case GNode::Prim: return test_prim(g.prim, s);
    case GNode::Prims:
      for (int i = g.a, e = g.a + g.b; i < e; ++i)
        if (!test_prim(gprims_[i], s)) return false;
      return true;
    case GNode::And:
      for (int i = 0; i < g.b; ++i)
        if (!eval_gen(gkids_[g.a + i], s)) return false;
      return true;
    case GNode::Or:
      for (int i = 0; i < g.b; ++i)
        if (eval_gen(gkids_[g.a + i], s)) return true;
      return false;
    case GNode::Not: return !eval_gen(g.a, s);
    case GNode::Cell: {
      const CellTest& t = cells_[g.a];
      const BitMatrix& m = matrices_[t.matrix];
      // Same arithmetic as eval_num on the GetIndex node.
      int64_t r = t.row_slot < 0 ? t.row_k : int64_t{get_num(s, atom_words_, t.row_slot)} + t.row_k;
      int64_t c = t.col_slot < 0 ? t.col_k : int64_t{get_num(s, atom_words_, t.col_slot)} + t.col_k;
      int64_t x = (r < 1 || r > m.rows || c < 1 || c > m.cols) ? -1 : m.get(static_cast<int>(r - 1), static_cast<int>(c - 1));
      return compare(x, t.cmp - CNode::Eq, t.value);
    }
    case GNode::Cond: return eval(g.a, s);
  }
  return false;
}

// Inlined into every evaluator of this file: it is the innermost test.
[[gnu::always_inline]] inline bool Task::test_prim(const CNode& n, const uint64_t* s) const {
  switch (n.op) {
    case CNode::Atom: return get_bit(s, n.a);
    case CNode::NotAtom: return !get_bit(s, n.a);
    case CNode::False: return false;
    default: {
      const int x = get_num(s, atom_words_, n.a);
      const int y = n.op == CNode::SlotConst ? n.b : get_num(s, atom_words_, n.b) + (n.c >> 3);
      return compare(x, n.c & 7, y);
    }
  }
}

bool Task::applicable(ActionId a, const uint64_t* s) const {
  for (int i = prim_begin_[a], e = prim_begin_[a + 1]; i < e; ++i)
    if (!test_prim(prims_[i], s)) return false;
  for (int i = rest_begin_[a], e = rest_begin_[a + 1]; i < e; ++i)
    if (!eval(rests_[i], s)) return false;
  return true;
}

bool Task::object_is_a(ObjectId o, const std::string& type) const {
  auto t = domain_->find_type(type);
  return t && domain_->is_subtype(problem_->objects[o].type, *t);
}

std::vector<ObjectId> Task::objects_of_type(const std::string& type) const {
  std::vector<ObjectId> out;
  for (int o = 0; o < num_objects(); ++o)
    if (object_is_a(o, type)) out.push_back(o);
  return out;
}

Task::AtomRef Task::atom(PredId pred, const std::vector<ObjectId>& args) const {
  auto k = key_of(pred, args);
  if (auto it = atom_index_.find(k); it != atom_index_.end()) return {it->second, false};
  return {-1, static_true_.count(k) > 0};
}

Task::AtomRef Task::atom(const std::string& pred, const std::vector<std::string>& args) const {
  auto p = domain_->find_predicate(pred);
  if (!p) throw InputError("unknown predicate '" + printable(pred) + "'");
  std::vector<ObjectId> ids;
  for (auto& a : args) {
    auto o = find_object(a);
    if (!o) throw InputError("unknown object '" + printable(a) + "'");
    ids.push_back(*o);
  }
  return atom(*p, ids);
}

Task::FluentRef Task::fluent(FuncId func, const std::vector<ObjectId>& args) const {
  auto k = key_of(func, args);
  if (auto it = fluent_index_.find(k); it != fluent_index_.end()) return {it->second, 0, nullptr};
  if (auto it = static_matrix_.find(k); it != static_matrix_.end()) return {-1, 0, &matrices_[it->second]};
  if (auto it = static_int_.find(k); it != static_int_.end()) return {-1, it->second, nullptr};
  return {-1, 0, nullptr};
}

Task::FluentRef Task::fluent(const std::string& func, const std::vector<std::string>& args) const {
  auto f = domain_->find_function(func);
  if (!f) throw InputError("unknown function '" + printable(func) + "'");
  std::vector<ObjectId> ids;
  for (auto& a : args) {
    auto o = find_object(a);
    if (!o) throw InputError("unknown object '" + printable(a) + "'");
    ids.push_back(*o);
  }
  return fluent(*f, ids);
}

std::string Task::atom_str(int bit) const {
  std::string s = "(" + domain_->predicates[atoms_[bit].first].name;
  for (auto o : atoms_[bit].second) s += " " + object_name(o);
  return s + ")";
}

std::string Task::fluent_str(int slot) const {
  std::string s = "(" + domain_->functions[fluents_[slot].first].name;
  for (auto o : fluents_[slot].second) s += " " + object_name(o);
  return s + ")";
}

void Task::set(State& s, const AtomRef& a, bool v) const {
  if (a.bit < 0) {
    if (a.value != v) throw std::logic_error("cannot change a static atom");
    return;
  }
  set_bit(s.data(), a.bit, v);
}

void Task::set(State& s, const FluentRef& f, int64_t v) const {
  if (f.slot < 0) {
    if (f.value != v) throw std::logic_error("cannot change a static fluent");
    return;
  }
  if (v < std::numeric_limits<int16_t>::min() || v > std::numeric_limits<int16_t>::max())
    throw std::out_of_range("fluent " + fluent_str(f.slot) + " value out of the int16 range");
  set_num(s.data(), atom_words_, f.slot, static_cast<int16_t>(v));
}

State Task::initial_state() const {
  State s = empty_state();
  for (int bit : init_bits_) set_bit(s.data(), bit, true);
  for (int slot = 0; slot < num_fluents(); ++slot) set(s, FluentRef{slot, 0, nullptr}, init_fluent_values_[slot]);
  return s;
}

std::string Task::state_str(const State& s) const {
  std::string out;
  for (int bit = 0; bit < num_atoms(); ++bit)
    if (get_bit(s.data(), bit)) out += atom_str(bit) + "\n";
  for (int slot = 0; slot < num_fluents(); ++slot)
    out += "(= " + fluent_str(slot) + " " + std::to_string(get_num(s.data(), atom_words_, slot)) + ")\n";
  return out;
}

std::string Task::action_name(ActionId a) const {
  const GroundAction& g = actions_[a];
  std::string s = "(" + domain_->actions[g.schema].name;
  for (auto o : g.args) s += " " + object_name(o);
  return s + ")";
}

std::optional<ActionId> Task::find_action(int schema, const std::vector<ObjectId>& args) const {
  auto it = action_index_.find(key_of(schema, args));
  if (it == action_index_.end()) return std::nullopt;
  return it->second;
}

std::optional<ActionId> Task::find_action(const std::string& text) const {
  SExpr e;
  try {
    e = read_one_sexpr(text, "<action>");
  } catch (const InputError&) {
    return std::nullopt;
  }
  if (!e.is_list || e.head().empty()) return std::nullopt;
  int schema = domain_->find_action(e.head());
  if (schema < 0) return std::nullopt;
  std::vector<ObjectId> args;
  for (size_t i = 1; i < e.items.size(); ++i) {
    auto o = find_object(e.items[i].atom);
    if (!o || e.items[i].is_list) return std::nullopt;
    args.push_back(*o);
  }
  return find_action(schema, args);
}

int64_t Task::eval_num(int n, const uint64_t* s) const {
  const NNode& x = nnodes_[n];
  switch (x.op) {
    case NNode::Const: return x.v;
    case NNode::Fluent: return get_num(s, atom_words_, static_cast<int>(x.v)) + x.a;
    case NNode::Add: return eval_num(x.a, s) + eval_num(x.b, s);
    case NNode::Sub: return eval_num(x.a, s) - eval_num(x.b, s);
    case NNode::Mul: return eval_num(x.a, s) * eval_num(x.b, s);
    case NNode::Div: {
      int64_t d = eval_num(x.b, s);
      return d == 0 ? 0 : eval_num(x.a, s) / d;
    }
    case NNode::Neg: return -eval_num(x.a, s);
    case NNode::GetIndex: {
      const BitMatrix& m = matrices_[x.v];
      int64_t r = eval_num(x.a, s), c = eval_num(x.b, s);
      if (r < 1 || r > m.rows || c < 1 || c > m.cols) return -1;  // off the matrix: neither true nor false
      return m.get(static_cast<int>(r - 1), static_cast<int>(c - 1));
    }
  }
  return 0;
}

bool Task::eval(CondId c, const uint64_t* s) const {
  const CNode& n = cnodes_[c];
  switch (n.op) {
    case CNode::True: return true;
    case CNode::False: return false;
    case CNode::Atom: return get_bit(s, n.a);
    case CNode::NotAtom: return !get_bit(s, n.a);
    case CNode::And:
      for (int i = 0; i < n.b; ++i)
        if (!eval(ckids_[n.a + i], s)) return false;
      return true;
    case CNode::Or:
      for (int i = 0; i < n.b; ++i)
        if (eval(ckids_[n.a + i], s)) return true;
      return false;
    case CNode::Not: return !eval(n.a, s);
    case CNode::Eq: return eval_num(n.a, s) == eval_num(n.b, s);
    case CNode::Ne: return eval_num(n.a, s) != eval_num(n.b, s);
    case CNode::Lt: return eval_num(n.a, s) < eval_num(n.b, s);
    case CNode::Le: return eval_num(n.a, s) <= eval_num(n.b, s);
    case CNode::Gt: return eval_num(n.a, s) > eval_num(n.b, s);
    case CNode::Ge: return eval_num(n.a, s) >= eval_num(n.b, s);
    case CNode::SlotConst:
    case CNode::SlotSlot: return test_prim(n, s);
  }
  return false;
}

void Task::apply_list(const EffectList& e, const uint64_t* src, uint64_t* dst, bool adds) const {
  if (!adds) {
    for (int bit : e.del) set_bit(dst, bit, false);
    return;
  }
  for (int bit : e.add) set_bit(dst, bit, true);
  for (const NumericEffect& ne : e.num) {
    int64_t v = eval_num(ne.expr, src);
    int64_t old = get_num(src, atom_words_, ne.slot);
    switch (ne.op) {
      case NumericEffect::Op::Assign: break;
      case NumericEffect::Op::Increase: v = old + v; break;
      case NumericEffect::Op::Decrease: v = old - v; break;
      case NumericEffect::Op::ScaleUp: v = old * v; break;
      case NumericEffect::Op::ScaleDown: v = v ? old / v : 0; break;
    }
    if (v < std::numeric_limits<int16_t>::min() || v > std::numeric_limits<int16_t>::max())
      throw std::out_of_range("fluent " + fluent_str(ne.slot) + " left the int16 range");
    set_num(dst, atom_words_, ne.slot, static_cast<int16_t>(v));
  }
}

void Task::apply(ActionId a, const uint64_t* src, uint64_t* dst) const {
  const GroundAction& g = actions_[a];
  if (dst != src) std::memcpy(dst, src, sizeof(uint64_t) * num_words_);
  if (g.cond_eff.empty()) {
    apply_list(g.eff, src, dst, false);
    apply_list(g.eff, src, dst, true);
    return;
  }
  // Conditions and right-hand sides read the old state; deletes before adds.
  std::vector<uint64_t> old;
  const uint64_t* from = src;
  if (dst == src) {
    old.assign(src, src + num_words_);
    from = old.data();
  }
  std::vector<char> fired(g.cond_eff.size());
  for (size_t i = 0; i < g.cond_eff.size(); ++i) fired[i] = eval(g.cond_eff[i].cond, from);
  apply_list(g.eff, from, dst, false);
  for (size_t i = 0; i < g.cond_eff.size(); ++i)
    if (fired[i]) apply_list(g.cond_eff[i].eff, from, dst, false);
  apply_list(g.eff, from, dst, true);
  for (size_t i = 0; i < g.cond_eff.size(); ++i)
    if (fired[i]) apply_list(g.cond_eff[i].eff, from, dst, true);
}

State Task::apply(const State& s, ActionId a) const {
  State out = s;
  apply(a, s.data(), out.data());
  return out;
}

void Task::applicable_actions(const uint64_t* s, std::vector<ActionId>& out) const {
  out.clear();
  int sources = 0;
  for (const Chunk& c : chunks_) {
    if (c.trigger >= 0 && !get_bit(s, c.trigger)) continue;
    uint64_t live = c.count == 64 ? ~uint64_t{0} : (uint64_t{1} << c.count) - 1;
    for (int i = c.lit_begin; i < c.lit_end && live; ++i) {
      const LitFilter& f = lit_filters_[i];
      live &= ~(get_bit(s, f.bit) ? f.kill_if_set : f.kill_if_clear);
    }
    if (!live) continue;
    ++sources;
    const ActionId* acts = &chunk_actions_[c.first];
    for (; live; live &= live - 1) {
      ActionId a = acts[__builtin_ctzll(live)];
      if (applicable_rest(a, s)) out.push_back(a);
    }
  }
  // Each chunk lists its actions in ascending order; several must be merged.
  if (sources > 1) std::sort(out.begin(), out.end());
}

std::vector<ActionId> Task::applicable_actions(const State& s) const {
  std::vector<ActionId> out;
  applicable_actions(s.data(), out);
  return out;
}

CondId Task::compile(const Condition& c, std::vector<ObjectId> binding) const {
  Grounder g(const_cast<Task&>(*this));
  g.pass_ = 2;
  // Reconstruct the pass-2 view: every interned atom/fluent is dynamic.
  for (auto& [k, bit] : atom_index_) g.modified_atoms_.insert(k);
  for (auto& [k, slot] : fluent_index_) g.modified_fluents_.insert(k);
  size_t atoms_before = atoms_.size(), fluents_before = fluents_.size();
  int id = g.cond(c, binding);
  if (atoms_.size() != atoms_before || fluents_.size() != fluents_before)
    throw std::logic_error("condition compilation created new state variables");
  return id;
}

CondId Task::compile_text(const std::string& text, const std::string& label) const {
  auto it = text_cache_.find(text);
  if (it != text_cache_.end()) return it->second;
  int nv = 0;
  // The problem's own goal, passed back as text (e.g. when the loader skipped
  // it): parse the expression as read so errors point into the problem file.
  const auto& own = problem_->goal_sexpr;
  Condition c = own && text == own->str() ? parse_condition(*domain_, *problem_, *own, &nv)
                                          : parse_condition_text(*domain_, *problem_, text, label, &nv);
  CondId id = compile(c, std::vector<ObjectId>(nv, -1));
  text_cache_[text] = id;
  return id;
}

std::string Task::explain_inapplicable(int schema, const std::vector<ObjectId>& args, const State& s) const {
  const ActionSchema& sc = domain_->actions[schema];
  if (args.size() != sc.param_types.size())
    return "arity mismatch: '" + sc.name + "' takes " + std::to_string(sc.param_types.size()) + " argument(s)";
  for (size_t i = 0; i < args.size(); ++i)
    if (!domain_->is_subtype(problem_->objects[args[i]].type, sc.param_types[i]))
      return "object '" + object_name(args[i]) + "' is not of type " + domain_->types[sc.param_types[i]].name;
  if (!sc.precondition) return "";
  std::vector<const Condition*> conj;
  std::function<void(const Condition&)> flat = [&](const Condition& c) {
    if (c.kind == Condition::Kind::And)
      for (auto& k : c.kids) flat(k);
    else
      conj.push_back(&c);
  };
  flat(*sc.precondition);
  std::vector<ObjectId> b(std::max<size_t>(sc.num_vars, args.size()), -1);
  std::copy(args.begin(), args.end(), b.begin());
  for (const Condition* c : conj) {
    CondId id = compile(*c, b);
    if (!eval(id, s.data())) return "precondition " + to_pddl(*domain_, *problem_, *c, sc.param_names, &b) + " is false";
  }
  return "";
}

}  // namespace clips::pddl
