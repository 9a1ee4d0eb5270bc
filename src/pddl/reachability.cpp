#include "pddl/reachability.hpp"

#include <algorithm>
#include <map>

#include "pddl/sexpr.hpp"
#include "util/memory.hpp"

namespace clips::pddl {

// ---------------------------------------------------------------- AtomTable

uint64_t AtomTable::hash(int pred, const ObjectId* a, int n) const {
  uint64_t h = 0x9e3779b97f4a7c15ull ^ (static_cast<uint64_t>(static_cast<uint32_t>(pred)) * 0xbf58476d1ce4e5b9ull);
  for (int i = 0; i < n; ++i) {
    h ^= static_cast<uint64_t>(static_cast<uint32_t>(a[i])) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0x94d049bb133111ebull;
  }
  h ^= h >> 31;
  return h;
}

int AtomTable::find(int pred, const ObjectId* a, int n) const {
  const uint64_t h = hash(pred, a, n);
  const size_t mask = table_.size() - 1;
  for (size_t i = h & mask;; i = (i + 1) & mask) {
    const int id = table_[i];
    if (id < 0) return -1;
    if (hashes_[static_cast<size_t>(id)] != h || len_[static_cast<size_t>(id)] != n) continue;
    const int* k = data_.data() + begin_[static_cast<size_t>(id)];
    if (k[0] == pred && std::equal(a, a + n, k + 1)) return id;
  }
}

int AtomTable::insert(int pred, const ObjectId* a, int n, bool* added) {
  const uint64_t h = hash(pred, a, n);
  const size_t mask = table_.size() - 1;
  size_t i = h & mask;
  for (;; i = (i + 1) & mask) {
    const int id = table_[i];
    if (id < 0) break;
    if (hashes_[static_cast<size_t>(id)] != h || len_[static_cast<size_t>(id)] != n) continue;
    const int* k = data_.data() + begin_[static_cast<size_t>(id)];
    if (k[0] == pred && std::equal(a, a + n, k + 1)) {
      *added = false;
      return id;
    }
  }
  const int id = size();
  begin_.push_back(static_cast<int>(data_.size()));
  data_.push_back(pred);
  data_.insert(data_.end(), a, a + n);
  len_.push_back(static_cast<uint8_t>(n));
  hashes_.push_back(h);
  table_[i] = id;
  *added = true;
  if (static_cast<size_t>(size()) * 2 > table_.size()) grow();
  return id;
}

void AtomTable::grow() {
  std::vector<int> bigger(table_.size() * 2, -1);
  const size_t mask = bigger.size() - 1;
  for (int id = 0; id < size(); ++id) {
    size_t i = hashes_[static_cast<size_t>(id)] & mask;
    while (bigger[i] >= 0) i = (i + 1) & mask;
    bigger[i] = id;
  }
  table_.swap(bigger);
}

// ---------------------------------------------------------------- rules

namespace {

struct RArg {
  int var = -1;       // a rule variable (schema slot), or
  ObjectId obj = -1;  // an object
};
struct RAtom {
  int pred = -1;  // a domain predicate, or num_preds + schema for "the action is reachable"
  std::vector<RArg> args;
};
struct Rule {
  std::vector<TypeId> var_types;  // per slot; -1 for slots the rule does not use
  std::vector<RAtom> body;        // positive atoms
  std::vector<std::pair<RArg, RArg>> equal, differ;
  std::vector<RAtom> heads;
  std::vector<int> needed;  // variables the heads read
};

RArg arg_of(const TermRef& t) { return t.is_var ? RArg{t.index, -1} : RArg{-1, t.index}; }

bool objects_compared(const Condition& c) {
  return c.kind == Condition::Kind::Equal && c.nums.size() == 2 && c.nums[0].kind == NumExpr::Kind::Object &&
         c.nums[1].kind == NumExpr::Kind::Object;
}

// What a state satisfying a condition has, as alternatives: the DNF of its
// atoms and object (in)equalities, through existentials; anything else (a
// negated atom, a universal, a number) counts as true. Each alternative is
// one rule body, as a translator splits disjunctive preconditions.
struct Part {
  std::vector<RAtom> atoms;
  std::vector<std::pair<RArg, RArg>> equal, differ;
};
constexpr size_t kMaxParts = 16;  // beyond: a conjunction keeps only its single-part conjuncts

void merge(Part& into, const Part& p) {
  into.atoms.insert(into.atoms.end(), p.atoms.begin(), p.atoms.end());
  into.equal.insert(into.equal.end(), p.equal.begin(), p.equal.end());
  into.differ.insert(into.differ.end(), p.differ.begin(), p.differ.end());
}

// No alternative: the condition is false.
std::vector<Part> parts(const Condition& c) {
  using K = Condition::Kind;
  switch (c.kind) {
    case K::Atom: {
      RAtom a{c.pred, {}};
      for (const TermRef& t : c.args) a.args.push_back(arg_of(t));
      Part p;
      p.atoms.push_back(std::move(a));
      return {p};
    }
    case K::And: {
      std::vector<std::vector<Part>> kids;
      size_t product = 1;
      for (const Condition& k : c.kids) {
        kids.push_back(parts(k));
        if (kids.back().empty()) return {};
        product = std::min<size_t>(product * kids.back().size(), kMaxParts + 1);
      }
      if (product > kMaxParts) {
        Part common;
        for (const auto& k : kids)
          if (k.size() == 1) merge(common, k[0]);
        return {common};
      }
      std::vector<Part> acc{Part{}};
      for (const auto& k : kids) {
        std::vector<Part> next;
        for (const Part& x : acc)
          for (const Part& y : k) {
            Part z = x;
            merge(z, y);
            next.push_back(std::move(z));
          }
        acc = std::move(next);
      }
      return acc;
    }
    case K::Or: {
      std::vector<Part> out;
      for (const Condition& k : c.kids) {
        auto ps = parts(k);
        out.insert(out.end(), ps.begin(), ps.end());
        if (out.size() > kMaxParts) return {Part{}};
      }
      return out;
    }
    case K::Exists: return parts(c.kids[0]);
    case K::False: return {};
    case K::Equal: {
      Part p;
      if (objects_compared(c)) p.equal.push_back({arg_of(c.nums[0].args[0]), arg_of(c.nums[1].args[0])});
      return {p};
    }
    case K::Not: {
      Part p;
      if (objects_compared(c.kids[0]))
        p.differ.push_back({arg_of(c.kids[0].nums[0].args[0]), arg_of(c.kids[0].nums[1].args[0])});
      return {p};
    }
    default: return {Part{}};  // a universal, implication, negation or number: may hold
  }
}

void slot_types(const Condition& c, std::vector<TypeId>& t) {
  if (c.kind == Condition::Kind::Exists || c.kind == Condition::Kind::Forall)
    for (size_t i = 0; i < c.var_types.size(); ++i) t[static_cast<size_t>(c.first_var) + i] = c.var_types[i];
  for (const Condition& k : c.kids) slot_types(k, t);
}

void slot_types(const Effect& e, std::vector<TypeId>& t) {
  if (e.kind == Effect::Kind::Forall)
    for (size_t i = 0; i < e.var_types.size(); ++i) t[static_cast<size_t>(e.first_var) + i] = e.var_types[i];
  if (e.kind == Effect::Kind::When) slot_types(e.cond, t);
  for (const Effect& k : e.kids) slot_types(k, t);
}

// Atoms and actions with more arguments are refused (the table keeps an
// arity in a byte; real domains stay below ten).
constexpr size_t kMaxArity = 64;

class Explorer {
 public:
  Explorer(const Domain& d, const Problem& p, const ReachabilityLimits& lim)
      : d_(d), p_(p), lim_(lim), num_preds_(static_cast<int>(d.predicates.size())),
        num_objects_(static_cast<int>(p.objects.size())) {
    if (lim.check_memory)
      if (auto h = util::memory_headroom()) headroom_ = *h;
  }

  Reachable run(const std::set<PredId>& keep_all) {
    make_rules();
    out_.tuples.assign(d_.actions.size(), {});
    schema_count_.assign(d_.actions.size(), 0);
    for (const InitAtom& a : p_.init_atoms) add(a.pred, a.args.data(), static_cast<int>(a.args.size()));
    for (PredId pred : keep_all) {
      const auto& types = d_.predicates[static_cast<size_t>(pred)].arg_types;
      std::vector<std::vector<ObjectId>> doms;
      for (TypeId t : types) doms.push_back(objects_of(t));
      std::vector<ObjectId> tuple(types.size());
      enumerate(doms, 0, tuple, [&] { add(pred, tuple.data(), static_cast<int>(tuple.size())); });
    }
    std::vector<ObjectId> binding;
    for (size_t r = 0; r < rules_.size(); ++r)
      if (rules_[r].body.empty()) {
        binding.assign(rules_[r].var_types.size(), -1);
        finish(static_cast<int>(r), binding);
      }
    for (size_t next = 0; next < queue_.size(); ++next) {
      if ((next & 1023) == 0) check_budgets();
      process(queue_[next]);
    }
    out_.num_actions = actions_;
    out_.counts = schema_count_;
    return std::move(out_);
  }

 private:
  // ------------------------------------------------------------ rules
  std::vector<ObjectId> objects_of(TypeId t) const {
    std::vector<ObjectId> out;
    for (size_t i = 0; i < p_.objects.size(); ++i)
      if (d_.is_subtype(p_.objects[i].type, t)) out.push_back(static_cast<ObjectId>(i));
    return out;
  }

  template <class F>
  static void enumerate(const std::vector<std::vector<ObjectId>>& doms, size_t k, std::vector<ObjectId>& tuple, F&& f) {
    if (k == doms.size()) return f();
    for (ObjectId o : doms[k]) {
      tuple[k] = o;
      enumerate(doms, k + 1, tuple, f);
    }
  }

  static void add_part(Rule& r, const Part& p) {
    r.body.insert(r.body.end(), p.atoms.begin(), p.atoms.end());
    r.equal.insert(r.equal.end(), p.equal.begin(), p.equal.end());
    r.differ.insert(r.differ.end(), p.differ.begin(), p.differ.end());
  }

  RAtom action_atom(int schema) const {
    RAtom a{num_preds_ + schema, {}};
    for (size_t i = 0; i < d_.actions[static_cast<size_t>(schema)].param_types.size(); ++i)
      a.args.push_back(RArg{static_cast<int>(i), -1});
    return a;
  }

  // The adds of `e` under the context of rule `into` go to its heads; a
  // conditional or universal effect opens a rule of its own, whose body is the
  // action's reachability (or the enclosing effect rule's body) and the
  // condition's positive atoms.
  void effect_rules(const Effect& e, Rule& into, bool top, int schema) {
    using K = Effect::Kind;
    switch (e.kind) {
      case K::And:
        for (const Effect& k : e.kids) effect_rules(k, into, top, schema);
        return;
      case K::Add: {
        RAtom a{e.pred, {}};
        for (const TermRef& t : e.args) a.args.push_back(arg_of(t));
        into.heads.push_back(std::move(a));
        return;
      }
      case K::When: case K::Forall: {
        for (const Part& part : e.kind == K::When ? parts(e.cond) : std::vector<Part>{Part{}}) {
          Rule child;
          child.var_types = into.var_types;
          if (top) {
            child.body.push_back(action_atom(schema));
          } else {
            child.body = into.body;
            child.equal = into.equal;
            child.differ = into.differ;
          }
          add_part(child, part);
          effect_rules(e.kids[0], child, false, schema);
          if (!child.heads.empty()) rules_.push_back(std::move(child));
        }
        return;
      }
      default: return;  // deletes and numbers add nothing
    }
  }

  void make_rules() {
    for (const PredicateDef& pd : d_.predicates)
      if (pd.arg_types.size() > kMaxArity)
        throw InputError(pd.loc, printable("predicate '" + pd.name + "' has " + std::to_string(pd.arg_types.size()) +
                                           " parameters; at most " + std::to_string(kMaxArity) + " are supported"));
    for (const ActionSchema& a : d_.actions)
      if (a.param_types.size() > kMaxArity)
        throw InputError(a.loc, printable("action '" + a.name + "' has " + std::to_string(a.param_types.size()) +
                                          " parameters; at most " + std::to_string(kMaxArity) + " are supported"));
    for (size_t s = 0; s < d_.actions.size(); ++s) {
      const ActionSchema& a = d_.actions[s];
      Rule r;
      r.var_types.assign(static_cast<size_t>(std::max<int>(a.num_vars, static_cast<int>(a.param_types.size()))), -1);
      for (size_t i = 0; i < a.param_types.size(); ++i) r.var_types[i] = a.param_types[i];
      if (a.precondition) slot_types(*a.precondition, r.var_types);
      slot_types(a.effect, r.var_types);
      const std::vector<Part> pre = a.precondition ? parts(*a.precondition) : std::vector<Part>{Part{}};
      if (pre.empty()) continue;  // never applicable
      r.heads.push_back(action_atom(static_cast<int>(s)));
      effect_rules(a.effect, r, true, static_cast<int>(s));  // r collects the unconditional adds
      for (const Part& part : pre) {
        Rule x = r;
        add_part(x, part);
        rules_.push_back(std::move(x));
      }
    }
    for (const DerivedRule& dr : d_.derived) {
      Rule r;
      r.var_types.assign(static_cast<size_t>(std::max<int>(dr.num_vars, static_cast<int>(dr.param_types.size()))), -1);
      for (size_t i = 0; i < dr.param_types.size(); ++i) r.var_types[i] = dr.param_types[i];
      slot_types(dr.body, r.var_types);
      RAtom h{dr.pred, {}};
      for (size_t i = 0; i < dr.param_types.size(); ++i) h.args.push_back(RArg{static_cast<int>(i), -1});
      r.heads.push_back(std::move(h));
      for (const Part& part : parts(dr.body)) {
        Rule x = r;
        add_part(x, part);
        rules_.push_back(std::move(x));
      }
    }
    // Per rule: which objects each variable may take, what the heads need,
    // and for each body atom, the join order of the others when it is the
    // new atom (most bound arguments first).
    allowed_.resize(rules_.size());
    order_.resize(rules_.size());
    triggers_.assign(static_cast<size_t>(num_preds_) + d_.actions.size(), {});
    for (size_t ri = 0; ri < rules_.size(); ++ri) {
      Rule& r = rules_[ri];
      allowed_[ri].assign(r.var_types.size(), {});
      for (size_t v = 0; v < r.var_types.size(); ++v) {
        if (r.var_types[v] < 0) continue;
        allowed_[ri][v].assign(static_cast<size_t>(num_objects_), 0);
        for (ObjectId o : objects_of(r.var_types[v])) allowed_[ri][v][static_cast<size_t>(o)] = 1;
      }
      std::vector<char> in_head(r.var_types.size(), 0);
      for (const RAtom& h : r.heads)
        for (const RArg& x : h.args)
          if (x.var >= 0 && !in_head[static_cast<size_t>(x.var)]) {
            in_head[static_cast<size_t>(x.var)] = 1;
            r.needed.push_back(x.var);
          }
      order_[ri].assign(r.body.size(), {});
      for (size_t i = 0; i < r.body.size(); ++i) {
        triggers_[static_cast<size_t>(r.body[i].pred)].push_back({static_cast<int>(ri), static_cast<int>(i)});
        std::vector<char> bound(r.var_types.size(), 0), used(r.body.size(), 0);
        auto bind = [&](const RAtom& a) {
          for (const RArg& x : a.args)
            if (x.var >= 0) bound[static_cast<size_t>(x.var)] = 1;
        };
        bind(r.body[i]);
        used[i] = 1;
        for (size_t k = 1; k < r.body.size(); ++k) {
          int best = -1, best_free = 0, best_bound = 0;
          for (size_t j = 0; j < r.body.size(); ++j) {
            if (used[j]) continue;
            int nfree = 0, nbound = 0;
            for (const RArg& x : r.body[j].args)
              (x.var >= 0 && !bound[static_cast<size_t>(x.var)] ? nfree : nbound)++;
            if (best < 0 || nfree < best_free || (nfree == best_free && nbound > best_bound)) {
              best = static_cast<int>(j);
              best_free = nfree;
              best_bound = nbound;
            }
          }
          used[static_cast<size_t>(best)] = 1;
          bind(r.body[static_cast<size_t>(best)]);
          order_[ri][i].push_back(best);
        }
      }
    }
    pred_allowed_.resize(static_cast<size_t>(num_preds_));
    for (int pr = 0; pr < num_preds_; ++pr) {
      const auto& types = d_.predicates[static_cast<size_t>(pr)].arg_types;
      pred_allowed_[static_cast<size_t>(pr)].assign(types.size(), {});
      for (size_t k = 0; k < types.size(); ++k) {
        pred_allowed_[static_cast<size_t>(pr)][k].assign(static_cast<size_t>(num_objects_), 0);
        for (ObjectId o : objects_of(types[k])) pred_allowed_[static_cast<size_t>(pr)][k][static_cast<size_t>(o)] = 1;
      }
    }
    index_.resize(static_cast<size_t>(num_preds_) + d_.actions.size());
    all_.resize(index_.size());
  }

  // ------------------------------------------------------------ joins
  void process(int id) {
    const int pred = out_.atoms.pred(id);
    const int n = out_.atoms.arity(id);
    const ObjectId* args = out_.atoms.args(id);
    auto& idx = index_[static_cast<size_t>(pred)];
    if (idx.empty() && n > 0) idx.assign(static_cast<size_t>(n), std::vector<std::vector<int>>(static_cast<size_t>(num_objects_)));
    for (int k = 0; k < n; ++k) idx[static_cast<size_t>(k)][static_cast<size_t>(args[k])].push_back(id);
    all_[static_cast<size_t>(pred)].push_back(id);
    for (const auto& [ri, pos] : triggers_[static_cast<size_t>(pred)]) {
      const Rule& r = rules_[static_cast<size_t>(ri)];
      binding_.assign(r.var_types.size(), -1);
      int undo[kMaxArity];
      int nundo = 0;
      if (!unify(ri, r.body[static_cast<size_t>(pos)], id, binding_, undo, nundo)) continue;
      join(ri, order_[static_cast<size_t>(ri)][static_cast<size_t>(pos)], 0, binding_);
    }
  }

  // Binds the variables of `a` to atom `id`'s objects; the newly bound ones
  // are listed in undo[] (at most an atom's arity).
  bool unify(int ri, const RAtom& a, int id, std::vector<ObjectId>& b, int* undo, int& nundo) const {
    const ObjectId* args = out_.atoms.args(id);
    const int n = out_.atoms.arity(id);
    if (n != static_cast<int>(a.args.size())) return false;
    for (int k = 0; k < n; ++k) {
      const RArg& x = a.args[static_cast<size_t>(k)];
      const ObjectId o = args[k];
      if (x.var < 0) {
        if (x.obj != o) return false;
      } else if (b[static_cast<size_t>(x.var)] < 0) {
        if (!allowed_[static_cast<size_t>(ri)][static_cast<size_t>(x.var)][static_cast<size_t>(o)]) return false;
        b[static_cast<size_t>(x.var)] = o;
        undo[nundo++] = x.var;
      } else if (b[static_cast<size_t>(x.var)] != o) {
        return false;
      }
    }
    return true;
  }

  void join(int ri, const std::vector<int>& order, size_t k, std::vector<ObjectId>& b) {
    const Rule& r = rules_[static_cast<size_t>(ri)];
    if (k == order.size()) return finish(ri, b);
    const RAtom& a = r.body[static_cast<size_t>(order[k])];
    // The candidates: the shortest index list of a bound argument, else all.
    const std::vector<int>* cands = &all_[static_cast<size_t>(a.pred)];
    const auto& idx = index_[static_cast<size_t>(a.pred)];
    if (!idx.empty())
      for (size_t j = 0; j < a.args.size(); ++j) {
        const RArg& x = a.args[j];
        const ObjectId o = x.var < 0 ? x.obj : b[static_cast<size_t>(x.var)];
        if (o < 0) continue;
        const std::vector<int>& l = idx[j][static_cast<size_t>(o)];
        if (l.size() < cands->size()) cands = &l;
      }
    for (size_t c = 0; c < cands->size(); ++c) {
      int undo[kMaxArity];
      int nundo = 0;
      if (unify(ri, a, (*cands)[c], b, undo, nundo) && constraints_hold(r, b)) join(ri, order, k + 1, b);
      for (int u = 0; u < nundo; ++u) b[static_cast<size_t>(undo[u])] = -1;
    }
  }

  static ObjectId value(const RArg& x, const std::vector<ObjectId>& b) {
    return x.var < 0 ? x.obj : b[static_cast<size_t>(x.var)];
  }
  // Constraints between objects: false only when both sides are known.
  bool constraints_hold(const Rule& r, const std::vector<ObjectId>& b) const {
    for (const auto& [x, y] : r.equal) {
      const ObjectId u = value(x, b), v = value(y, b);
      if (u >= 0 && v >= 0 && u != v) return false;
    }
    for (const auto& [x, y] : r.differ) {
      const ObjectId u = value(x, b), v = value(y, b);
      if (u >= 0 && v >= 0 && u == v) return false;
    }
    return true;
  }

  // A body matched: bind what the heads read and no atom bound (every object
  // of its type), then add the heads.
  void finish(int ri, std::vector<ObjectId>& b) {
    const Rule& r = rules_[static_cast<size_t>(ri)];
    if (!constraints_hold(r, b)) return;
    for (int v : r.needed)
      if (b[static_cast<size_t>(v)] < 0) {
        // Equal to something known: only that object.
        for (const auto& [x, y] : r.equal) {
          const ObjectId o = x.var == v ? value(y, b) : y.var == v ? value(x, b) : -1;
          if (o < 0) continue;
          if (allowed_[static_cast<size_t>(ri)][static_cast<size_t>(v)][static_cast<size_t>(o)]) {
            b[static_cast<size_t>(v)] = o;
            finish(ri, b);
          }
          b[static_cast<size_t>(v)] = -1;
          return;
        }
        for (ObjectId o = 0; o < num_objects_; ++o) {
          if (!allowed_[static_cast<size_t>(ri)][static_cast<size_t>(v)][static_cast<size_t>(o)]) continue;
          b[static_cast<size_t>(v)] = o;
          finish(ri, b);
        }
        b[static_cast<size_t>(v)] = -1;
        return;
      }
    for (const RAtom& h : r.heads) {
      head_.clear();
      bool fits = true;
      for (size_t k = 0; k < h.args.size(); ++k) {
        const ObjectId o = value(h.args[k], b);
        if (h.pred < num_preds_ && !pred_allowed_[static_cast<size_t>(h.pred)][k][static_cast<size_t>(o)]) fits = false;
        head_.push_back(o);
      }
      if (fits) add(h.pred, head_.data(), static_cast<int>(head_.size()));
    }
  }

  void add(int pred, const ObjectId* args, int n) {
    bool added = false;
    const int id = out_.atoms.insert(pred, args, n, &added);
    if (!added) return;
    queue_.push_back(id);
    if (pred < num_preds_) return;
    const size_t schema = static_cast<size_t>(pred - num_preds_);
    out_.tuples[schema].insert(out_.tuples[schema].end(), args, args + n);
    ++schema_count_[schema];
    ++actions_;
    if (actions_ > lim_.max_actions) refuse();
    if ((actions_ & 4095) == 0) check_budgets();
  }

  // ------------------------------------------------------------ limits
  std::string counts() const {
    std::vector<std::pair<int64_t, size_t>> by;
    for (size_t s = 0; s < schema_count_.size(); ++s)
      if (schema_count_[s] > 0) by.push_back({schema_count_[s], s});
    std::sort(by.rbegin(), by.rend());
    std::string out;
    for (size_t i = 0; i < by.size() && i < 4; ++i)
      out += (i ? ", action '" : "action '") + d_.actions[by[i].second].name + "' " + std::to_string(by[i].first);
    if (by.size() > 4) out += ", ...";
    return out;
  }

  // Located at the action with the most ground actions so far.
  [[noreturn]] void refuse() const {
    const size_t top = static_cast<size_t>(std::max_element(schema_count_.begin(), schema_count_.end()) - schema_count_.begin());
    throw InputError(d_.actions[top].loc,
                     printable("more than " + std::to_string(lim_.max_actions) +
                               " ground actions are reachable from the initial state (found so far: " + counts() +
                               "); the limit is " + std::to_string(lim_.max_actions) +
                               " ground actions (raise it with --max-ground-actions)"));
  }

  void check_budgets() const {
    if (lim_.deadline != std::chrono::steady_clock::time_point::max() && std::chrono::steady_clock::now() >= lim_.deadline)
      throw TimeLimitError(printable(lim_.deadline_label + " reached while grounding (reachability analysis: " +
                                     std::to_string(out_.atoms.size()) + " atoms and " + std::to_string(actions_) +
                                     " ground actions reached so far)"));
    if (!headroom_) return;
    const int64_t need = static_cast<int64_t>(out_.atoms.bytes()) + actions_ * lim_.bytes_per_action;
    if (need <= headroom_->bytes) return;
    throw MemoryLimitError(printable("grounding is on course to need about " + util::format_bytes(need) + " (" +
                                     std::to_string(actions_) + " reachable ground actions so far: " + counts() +
                                     "), but only " + util::format_bytes(headroom_->bytes) + " is left (" +
                                     headroom_->bound + "): stopped before memory ran out"));
  }

  const Domain& d_;
  const Problem& p_;
  ReachabilityLimits lim_;
  std::optional<util::MemoryHeadroom> headroom_;
  int num_preds_, num_objects_;
  std::vector<Rule> rules_;
  std::vector<std::vector<std::vector<char>>> allowed_;       // rule -> var -> object
  std::vector<std::vector<std::vector<char>>> pred_allowed_;  // predicate -> position -> object
  std::vector<std::vector<std::vector<int>>> order_;          // rule -> trigger position -> join order
  std::vector<std::vector<std::pair<int, int>>> triggers_;    // predicate -> (rule, body position)
  // Processed atoms: per predicate, per position and object; and all of them.
  std::vector<std::vector<std::vector<std::vector<int>>>> index_;
  std::vector<std::vector<int>> all_;
  std::vector<int> queue_;
  std::vector<ObjectId> binding_, head_;
  std::vector<int64_t> schema_count_;
  int64_t actions_ = 0;
  Reachable out_;
};

}  // namespace

Reachable explore_reachable(const Domain& d, const Problem& p, const std::set<PredId>& keep_all,
                            const ReachabilityLimits& limits) {
  return Explorer(d, p, limits).run(keep_all);
}

}  // namespace clips::pddl
