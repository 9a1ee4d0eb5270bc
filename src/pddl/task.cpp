// Runtime queries of a grounded Task: lookups, names, evaluation of compiled
// conditions and expressions, and applying actions. All read-only.
#include <algorithm>
#include <functional>
#include <limits>

#include "pddl/parser.hpp"
#include "pddl/task.hpp"
#include "pddl/task_inline.hpp"

namespace clips::pddl {

using detail::key_of;

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
  if (v < kMinFluent || v > kMaxFluent)
    throw InputError("fluent " + fluent_str(f.slot) + " cannot be set to " + std::to_string(v) +
                     ": states hold the numeric fluents actions change as 16-bit integers (" +
                     std::to_string(kMinFluent) + ".." + std::to_string(kMaxFluent) + ")");
  set_num(s.data(), atom_words_, f.slot, static_cast<int16_t>(v));
}

State Task::initial_state() const {
  State s = empty_state();
  for (int bit : init_bits_) set_bit(s.data(), bit, true);
  for (int slot = 0; slot < num_fluents(); ++slot) set(s, FluentRef{slot, 0, nullptr}, init_fluent_values_[slot]);
  evaluate_axioms(s.data());
  return s;
}

void Task::prepare_axioms() {
  derived_.clear();
  derived_mask_.clear();
  readers_begin_.clear();
  readers_.clear();
  bool any = false;
  std::vector<char> flag(static_cast<size_t>(num_atoms()), 0);
  for (int bit = 0; bit < num_atoms(); ++bit)
    if (domain_->predicates[static_cast<size_t>(atoms_[static_cast<size_t>(bit)].first)].derived) flag[static_cast<size_t>(bit)] = any = 1;
  if (!any) return;
  derived_ = std::move(flag);
  derived_mask_.assign(static_cast<size_t>(atom_words_), 0);
  for (int bit = 0; bit < num_atoms(); ++bit)
    if (derived_[static_cast<size_t>(bit)]) derived_mask_[static_cast<size_t>(bit >> 6)] |= uint64_t{1} << (bit & 63);
  // The stratum of each derived bit (that of its rules), then per bit the
  // rules of its own stratum that read it.
  std::vector<int> stratum_of(static_cast<size_t>(num_atoms()), -1);
  for (size_t k = 0; k + 1 < stratum_begin_.size(); ++k)
    for (int i = stratum_begin_[k]; i < stratum_begin_[k + 1]; ++i)
      stratum_of[static_cast<size_t>(axioms_[static_cast<size_t>(i)].head)] = static_cast<int>(k);
  std::vector<std::vector<int>> readers(static_cast<size_t>(num_atoms()));
  std::vector<int> bits;
  std::function<void(CondId)> reads = [&](CondId c) {
    const CNode& n = pool_.cnodes[static_cast<size_t>(c)];
    switch (n.op) {
      case CNode::Atom: case CNode::NotAtom: bits.push_back(n.a); return;
      case CNode::And: case CNode::Or:
        for (int i = 0; i < n.b; ++i) reads(pool_.ckids[static_cast<size_t>(n.a + i)]);
        return;
      case CNode::Not: reads(n.a); return;
      default: return;
    }
  };
  for (size_t k = 0; k + 1 < stratum_begin_.size(); ++k)
    for (int i = stratum_begin_[k]; i < stratum_begin_[k + 1]; ++i) {
      bits.clear();
      reads(axioms_[static_cast<size_t>(i)].body);
      std::sort(bits.begin(), bits.end());
      bits.erase(std::unique(bits.begin(), bits.end()), bits.end());
      for (int b : bits)
        if (stratum_of[static_cast<size_t>(b)] == static_cast<int>(k)) readers[static_cast<size_t>(b)].push_back(i);
    }
  readers_begin_.assign(1, 0);
  for (const auto& r : readers) {
    readers_.insert(readers_.end(), r.begin(), r.end());
    readers_begin_.push_back(static_cast<int>(readers_.size()));
  }
}

void Task::evaluate_axioms(uint64_t* s) const {
  if (derived_.empty()) return;
  for (size_t w = 0; w < derived_mask_.size(); ++w) s[w] &= ~derived_mask_[w];
  // Stratum by stratum: every rule once, then again the rules reading an
  // atom that became true (within a stratum, rules read their own stratum's
  // atoms only positively, so the fixpoint only grows).
  thread_local std::vector<int> queue;
  for (size_t k = 0; k + 1 < stratum_begin_.size(); ++k) {
    queue.clear();
    auto fire = [&](int i) {
      const Axiom& x = axioms_[static_cast<size_t>(i)];
      if (get_bit(s, x.head) || !eval(x.body, s)) return;
      set_bit(s, x.head, true);
      for (int r = readers_begin_[static_cast<size_t>(x.head)]; r < readers_begin_[static_cast<size_t>(x.head) + 1]; ++r)
        queue.push_back(readers_[static_cast<size_t>(r)]);
    };
    for (int i = stratum_begin_[k]; i < stratum_begin_[k + 1]; ++i) fire(i);
    while (!queue.empty()) {
      const int i = queue.back();
      queue.pop_back();
      fire(i);
    }
  }
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

int64_t Task::eval_num(const Pool& pool, int n, const uint64_t* s) const {
  const NNode& x = pool.nnodes[n];
  switch (x.op) {
    case NNode::Const: return x.v;
    case NNode::Fluent: return get_num(s, atom_words_, static_cast<int>(x.v)) + x.a;
    case NNode::Add: return eval_num(pool, x.a, s) + eval_num(pool, x.b, s);
    case NNode::Sub: return eval_num(pool, x.a, s) - eval_num(pool, x.b, s);
    case NNode::Mul: return eval_num(pool, x.a, s) * eval_num(pool, x.b, s);
    case NNode::Div: {
      int64_t d = eval_num(pool, x.b, s);
      if (d == 0) throw InputError(pool.div_locs[static_cast<size_t>(x.v)], "division by zero: the divisor is 0 in this state");
      return eval_num(pool, x.a, s) / d;
    }
    case NNode::Neg: return -eval_num(pool, x.a, s);
    case NNode::GetIndex: {
      const BitMatrix& m = matrices_[x.v];
      int64_t r = eval_num(pool, x.a, s), c = eval_num(pool, x.b, s);
      if (r < 1 || r > m.rows || c < 1 || c > m.cols) return -1;  // off the matrix: neither true nor false
      return m.get(static_cast<int>(r - 1), static_cast<int>(c - 1));
    }
  }
  return 0;
}

bool Task::eval_in(const Pool& pool, CondId c, const uint64_t* s) const {
  const CNode& n = pool.cnodes[c];
  switch (n.op) {
    case CNode::True: return true;
    case CNode::False: return false;
    case CNode::Atom: return get_bit(s, n.a);
    case CNode::NotAtom: return !get_bit(s, n.a);
    case CNode::And:
      for (int i = 0; i < n.b; ++i)
        if (!eval_in(pool, pool.ckids[n.a + i], s)) return false;
      return true;
    case CNode::Or:
      for (int i = 0; i < n.b; ++i)
        if (eval_in(pool, pool.ckids[n.a + i], s)) return true;
      return false;
    case CNode::Not: return !eval_in(pool, n.a, s);
    case CNode::Eq: return eval_num(pool, n.a, s) == eval_num(pool, n.b, s);
    case CNode::Ne: return eval_num(pool, n.a, s) != eval_num(pool, n.b, s);
    case CNode::Lt: return eval_num(pool, n.a, s) < eval_num(pool, n.b, s);
    case CNode::Le: return eval_num(pool, n.a, s) <= eval_num(pool, n.b, s);
    case CNode::Gt: return eval_num(pool, n.a, s) > eval_num(pool, n.b, s);
    case CNode::Ge: return eval_num(pool, n.a, s) >= eval_num(pool, n.b, s);
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
    int64_t v = eval_num(pool_, ne.expr, src);
    int64_t old = get_num(src, atom_words_, ne.slot);
    switch (ne.op) {
      case NumericEffect::Op::Assign: break;
      case NumericEffect::Op::Increase: v = old + v; break;
      case NumericEffect::Op::Decrease: v = old - v; break;
      case NumericEffect::Op::ScaleUp: v = old * v; break;
      case NumericEffect::Op::ScaleDown:
        if (v == 0) throw InputError("(scale-down " + fluent_str(ne.slot) + " ...) divides by zero in this state");
        v = old / v;
        break;
    }
    if (v < kMinFluent || v > kMaxFluent)
      throw InputError("fluent " + fluent_str(ne.slot) + " would become " + std::to_string(v) +
                       ": states hold the numeric fluents actions change as 16-bit integers (" +
                       std::to_string(kMinFluent) + ".." + std::to_string(kMaxFluent) +
                       "), and this plan goes beyond them");
    set_num(dst, atom_words_, ne.slot, static_cast<int16_t>(v));
  }
}

void Task::apply(ActionId a, const uint64_t* src, uint64_t* dst) const {
  const GroundAction& g = actions_[a];
  if (dst != src) std::memcpy(dst, src, sizeof(uint64_t) * num_words_);
  if (g.cond_eff.empty()) {
    apply_list(g.eff, src, dst, false);
    apply_list(g.eff, src, dst, true);
    if (!derived_.empty()) evaluate_axioms(dst);
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
  if (!derived_.empty()) evaluate_axioms(dst);
}

State Task::apply(const State& s, ActionId a) const {
  State out = s;
  apply(a, s.data(), out.data());
  return out;
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
    if (!compile(*c, b).holds(s)) return "precondition " + to_pddl(*domain_, *problem_, *c, sc.param_names, &b) + " is false";
  }
  return "";
}

}  // namespace clips::pddl
