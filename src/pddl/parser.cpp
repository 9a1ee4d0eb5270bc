#include "pddl/parser.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <set>

namespace clips::pddl {

// ---------------------------------------------------------------- Domain lookups

std::optional<TypeId> Domain::find_type(const std::string& n) const {
  for (size_t i = 0; i < types.size(); ++i)
    if (types[i].name == n) return static_cast<TypeId>(i);
  return std::nullopt;
}
std::optional<PredId> Domain::find_predicate(const std::string& n) const {
  for (size_t i = 0; i < predicates.size(); ++i)
    if (predicates[i].name == n) return static_cast<PredId>(i);
  return std::nullopt;
}
std::optional<FuncId> Domain::find_function(const std::string& n) const {
  for (size_t i = 0; i < functions.size(); ++i)
    if (functions[i].name == n) return static_cast<FuncId>(i);
  return std::nullopt;
}
int Domain::find_action(const std::string& n) const {
  for (size_t i = 0; i < actions.size(); ++i)
    if (actions[i].name == n) return static_cast<int>(i);
  return -1;
}
bool Domain::is_subtype(TypeId t, TypeId ancestor) const {
  // Unions: every member of `t` within `ancestor`; `t` within some member.
  if (t >= 0 && !types[t].either.empty()) {
    for (TypeId m : types[t].either)
      if (!is_subtype(m, ancestor)) return false;
    return true;
  }
  if (ancestor >= 0 && !types[ancestor].either.empty()) {
    for (TypeId m : types[ancestor].either)
      if (is_subtype(t, m)) return true;
    return false;
  }
  for (int guard = 0; t >= 0 && guard <= static_cast<int>(types.size()); ++guard) {
    if (t == ancestor) return true;
    t = types[t].parent;
  }
  return false;
}
std::optional<ObjectId> Problem::find_object(const std::string& n) const {
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == n) return static_cast<ObjectId>(i);
  return std::nullopt;
}

namespace {

const std::set<std::string> kSupportedRequirements = {
    ":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions", ":equality",
    ":existential-preconditions", ":universal-preconditions", ":quantified-preconditions",
    ":conditional-effects", ":adl", ":fluents", ":numeric-fluents", ":action-costs", ":derived-predicates"};

// Messages quote input text (names, expressions): escape control bytes in them.
[[noreturn]] void fail(const SourceLoc& loc, const std::string& msg) { throw InputError(loc, printable(msg)); }
[[noreturn]] void fail(const SExpr& e, const std::string& msg) { fail(e.loc, msg); }

bool is_integer(const std::string& s) {
  if (s.empty()) return false;
  size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

// The value of an integer literal (is_integer); one beyond int64 is an input
// error at the literal rather than an exception from std::stoll.
// A token meant as a number that is not a PDDL integer: "1e6", "0x10",
// "1.5", "inf", "nan", "-.5". Read as a name it would be "unknown object".
bool looks_numeric(const std::string& s) {
  size_t i = (s.size() > 1 && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (i >= s.size()) return false;
  const std::string rest = s.substr(i);
  if (rest == "inf" || rest == "infinity" || rest == "nan") return true;
  return std::isdigit(static_cast<unsigned char>(rest[0])) ||
         (rest[0] == '.' && rest.size() > 1 && std::isdigit(static_cast<unsigned char>(rest[1])));
}

std::string not_an_integer(const std::string& s) {
  const std::string what = s.find_first_of("xX") != std::string::npos ? "a hexadecimal number"
                           : s.find_first_of("eE") != std::string::npos && s.find_first_of("iI") == std::string::npos
                               ? "a number in exponent notation"
                           : s.find('.') != std::string::npos ? "a number with a fraction"
                           : s.find_first_not_of("+-0123456789") != std::string::npos ? "not a number PDDL allows"
                                                                                      : "a number";
  return "'" + s + "' is " + what + ": numbers here are integers written in decimal digits (e.g. 1000000); "
         "non-integer, infinite and hexadecimal values are not supported";
}

int64_t integer_value(const SExpr& e) {
  const char* first = e.atom.data() + (e.atom[0] == '+' ? 1 : 0);
  const char* last = e.atom.data() + e.atom.size();
  int64_t v = 0;
  auto [end, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || end != last)
    fail(e, "integer " + e.atom + " is out of range: integers must be between " +
                std::to_string(std::numeric_limits<int64_t>::min()) + " and " +
                std::to_string(std::numeric_limits<int64_t>::max()));
  return v;
}

const SExpr& expect_list(const SExpr& e, const std::string& what) {
  if (!e.is_list) fail(e, "expected " + what + ", found '" + e.atom + "'");
  return e;
}

// A name with type, from a PDDL typed list such as `a b - t c`.
struct TypedName {
  std::string name;
  std::string type;  // "object" when untyped; "(either a b)" for a union
  SourceLoc loc;
  SourceLoc type_loc;  // where the type was written (the name's own when untyped)
};

// The name of the union type `(either a b ...)`, as the domain's type table has it.
std::string either_name(const SExpr& e) {
  std::string n = "(either";
  for (size_t i = 1; i < e.items.size(); ++i) n += " " + e.items[i].atom;
  return n + ")";
}

std::vector<TypedName> typed_list(const std::vector<SExpr>& items, size_t from, const SExpr& owner) {
  std::vector<TypedName> out;
  std::vector<TypedName> pending;
  for (size_t i = from; i < items.size(); ++i) {
    const SExpr& it = items[i];
    if (it.is_list) fail(it, "expected a name in a typed list, found a list");
    if (it.atom == "-") {
      if (i + 1 >= items.size()) fail(it, "expected a type after '-'");
      const SExpr& t = items[i + 1];
      if (t.is_list && t.head() != "either") fail(t, "expected a type name after '-'");
      if (pending.empty()) fail(it, "'-' with no names before it");
      for (auto& p : pending) {
        p.type = t.is_list ? either_name(t) : t.atom;
        p.type_loc = t.loc;
        out.push_back(p);
      }
      pending.clear();
      ++i;
    } else {
      pending.push_back(TypedName{it.atom, "object", it.loc, it.loc});
    }
  }
  (void)owner;
  for (auto& p : pending) out.push_back(p);
  return out;
}

// ---------------------------------------------------------------- Expression parsing

struct Scope {
  std::vector<std::pair<std::string, TypeId>> vars;  // slot -> (name, type)
  std::vector<int> visible;                          // slots in scope, innermost last
  int num_slots() const { return static_cast<int>(vars.size()); }
};

class ExprParser {
 public:
  ExprParser(const Domain& d, const Problem* p) : d_(d), p_(p) {}

  Scope scope;

  // The reader bounds nesting, but expressions may also be built in code: the
  // grounder recurses over what this produces, so check the bound again.
  class Nested {
   public:
    Nested(ExprParser& p, const SExpr& e) : p_(p) {
      if (++p_.depth_ > kMaxNesting) {
        --p_.depth_;
        fail(e, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
      }
    }
    ~Nested() { --p_.depth_; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

   private:
    ExprParser& p_;
  };

  TermRef term(const SExpr& e, TypeId* type_out) {
    if (e.is_list) fail(e, "expected a variable or object, found a list");
    if (!e.atom.empty() && e.atom[0] == '?') {
      std::string n = e.atom.substr(1);
      for (auto it = scope.visible.rbegin(); it != scope.visible.rend(); ++it) {
        if (scope.vars[*it].first == n) {
          if (type_out) *type_out = scope.vars[*it].second;
          return TermRef{true, *it};
        }
      }
      fail(e, "unknown variable '" + e.atom + "'");
    }
    auto o = find_object(e.atom);
    if (!o) fail(e, "unknown object '" + e.atom + "'");
    if (type_out) *type_out = object_type(*o);
    return TermRef{false, *o};
  }

  std::optional<ObjectId> find_object(const std::string& n) const {
    if (p_) return p_->find_object(n);
    for (size_t i = 0; i < d_.constants.size(); ++i)
      if (d_.constants[i].name == n) return static_cast<ObjectId>(i);
    return std::nullopt;
  }
  TypeId object_type(ObjectId o) const { return p_ ? p_->objects[o].type : d_.constants[o].type; }

  void check_arg_type(const SExpr& at, TypeId given, TypeId wanted, bool is_var,
                      const std::string& what) {
    if (d_.is_subtype(given, wanted)) return;
    // A variable of a wider type is allowed (it simply fails for other objects).
    if (is_var && d_.is_subtype(wanted, given)) return;
    fail(at, "type mismatch in " + what + ": expected " + d_.types[wanted].name + ", got " +
                 d_.types[given].name);
  }

  std::vector<TermRef> args_for(const SExpr& e, const std::vector<TypeId>& types,
                                const std::string& what) {
    size_t n = e.items.size() - 1;
    if (n != types.size())
      fail(e, "arity mismatch: " + what + " takes " + std::to_string(types.size()) +
                  " argument(s), given " + std::to_string(n));
    std::vector<TermRef> out;
    for (size_t i = 0; i < n; ++i) {
      TypeId t = 0;
      TermRef r = term(e.items[i + 1], &t);
      check_arg_type(e.items[i + 1], t, types[i], r.is_var, what);
      out.push_back(r);
    }
    return out;
  }

  // Opens a quantifier scope; returns (first slot, types, names).
  void open_vars(const SExpr& list, Condition* c_or_null, Effect* e_or_null) {
    expect_list(list, "a variable list");
    auto names = typed_list(list.items, 0, list);
    int first = scope.num_slots();
    std::vector<TypeId> types;
    std::vector<std::string> vnames;
    for (auto& tn : names) {
      if (tn.name.empty() || tn.name[0] != '?')
        fail(tn.loc, "expected a variable (starting with '?'), found '" + tn.name + "'");
      if (std::find(vnames.begin(), vnames.end(), tn.name.substr(1)) != vnames.end())
        fail(tn.loc, "variable '" + tn.name + "' is declared twice in one list");
      auto t = d_.find_type(tn.type);
      if (!t) fail(tn.loc, "unknown type '" + tn.type + "'");
      scope.vars.push_back({tn.name.substr(1), *t});
      scope.visible.push_back(scope.num_slots() - 1);
      types.push_back(*t);
      vnames.push_back(tn.name.substr(1));
    }
    if (c_or_null) {
      c_or_null->first_var = first;
      c_or_null->var_types = types;
      c_or_null->var_names = vnames;
    }
    if (e_or_null) {
      e_or_null->first_var = first;
      e_or_null->var_types = types;
    }
  }
  void close_vars(size_t n) { scope.visible.resize(scope.visible.size() - n); }

  bool names_zero_ary_function(const std::string& s) const {
    auto f = d_.find_function(s);
    return f && d_.functions[*f].arg_types.empty();
  }

  NumExpr num(const SExpr& e) {
    Nested guard(*this, e);
    NumExpr x;
    x.loc = e.loc;
    if (!e.is_list) {
      if (is_integer(e.atom)) {
        x.kind = NumExpr::Kind::Const;
        x.value = integer_value(e);
      } else if (e.atom == "true" || e.atom == "false") {
        x.kind = NumExpr::Kind::Const;
        x.value = e.atom == "true";
        x.boolean = true;
      } else if (names_zero_ary_function(e.atom)) {
        x.kind = NumExpr::Kind::Fluent;
        x.func = *d_.find_function(e.atom);
      } else if (looks_numeric(e.atom) && !find_object(e.atom)) {
        fail(e, not_an_integer(e.atom));
      } else {
        x.kind = NumExpr::Kind::Object;
        x.args.push_back(term(e, nullptr));
      }
      return x;
    }
    const std::string& h = e.head();
    auto n = e.items.size() - 1;
    auto operands = [&](size_t want_min, size_t want_max) {
      if (n < want_min || n > want_max)
        fail(e, "arity mismatch: '" + h + "' given " + std::to_string(n) + " argument(s)");
      for (size_t i = 1; i <= n; ++i) x.kids.push_back(num(e.items[i]));
    };
    if (h == "+" || h == "*") {
      x.kind = h == "+" ? NumExpr::Kind::Add : NumExpr::Kind::Mul;
      operands(2, 2);
    } else if (h == "-") {
      operands(1, 2);
      x.kind = n == 1 ? NumExpr::Kind::Neg : NumExpr::Kind::Sub;
    } else if (h == "/") {
      x.kind = NumExpr::Kind::Div;
      operands(2, 2);
    } else if (h == "new-bit-matrix") {
      x.kind = NumExpr::Kind::NewMatrix;
      operands(3, 3);
    } else if (h == "set-index") {
      x.kind = NumExpr::Kind::SetIndex;
      operands(4, 4);
    } else if (h == "get-index") {
      x.kind = NumExpr::Kind::GetIndex;
      operands(3, 3);
    } else if (h == "width" || h == "height") {
      x.kind = h == "width" ? NumExpr::Kind::Width : NumExpr::Kind::Height;
      operands(1, 1);
    } else if (!h.empty()) {
      auto f = d_.find_function(h);
      if (!f) fail(e, "unknown function '" + h + "'");
      x.kind = NumExpr::Kind::Fluent;
      x.func = *f;
      x.args = args_for(e, d_.functions[*f].arg_types, "function '" + h + "'");
    } else {
      fail(e, "expected a numeric expression");
    }
    return x;
  }

  Condition cond(const SExpr& e) {
    Nested guard(*this, e);
    Condition c;
    c.loc = e.loc;
    if (!e.is_list) {
      if (e.atom == "true") return c;
      fail(e, "expected a condition, found '" + e.atom + "'");
    }
    if (e.items.empty()) {  // () is the empty conjunction
      c.kind = Condition::Kind::And;
      return c;
    }
    const std::string& h = e.head();
    size_t n = e.items.size() - 1;
    if (h == "and" || h == "or") {
      c.kind = h == "and" ? Condition::Kind::And : Condition::Kind::Or;
      for (size_t i = 1; i <= n; ++i) c.kids.push_back(cond(e.items[i]));
    } else if (h == "not") {
      if (n != 1) fail(e, "arity mismatch: 'not' takes 1 argument, given " + std::to_string(n));
      c.kind = Condition::Kind::Not;
      c.kids.push_back(cond(e.items[1]));
    } else if (h == "imply") {
      if (n != 2) fail(e, "arity mismatch: 'imply' takes 2 arguments, given " + std::to_string(n));
      c.kind = Condition::Kind::Imply;
      c.kids.push_back(cond(e.items[1]));
      c.kids.push_back(cond(e.items[2]));
    } else if (h == "exists" || h == "forall") {
      if (n != 2) fail(e, "expected (" + h + " (variables) condition)");
      c.kind = h == "exists" ? Condition::Kind::Exists : Condition::Kind::Forall;
      open_vars(e.items[1], &c, nullptr);
      c.kids.push_back(cond(e.items[2]));
      close_vars(c.var_types.size());
    } else if (h == "=" || h == "<" || h == "<=" || h == ">" || h == ">=") {
      if (n != 2) fail(e, "arity mismatch: '" + h + "' takes 2 arguments, given " + std::to_string(n));
      c.kind = h == "="    ? Condition::Kind::Equal
               : h == "<"  ? Condition::Kind::Less
               : h == "<=" ? Condition::Kind::LessEq
               : h == ">"  ? Condition::Kind::Greater
                           : Condition::Kind::GreaterEq;
      c.nums.push_back(num(e.items[1]));
      c.nums.push_back(num(e.items[2]));
      bool obj0 = c.nums[0].kind == NumExpr::Kind::Object;
      bool obj1 = c.nums[1].kind == NumExpr::Kind::Object;
      if ((obj0 || obj1) && (c.kind != Condition::Kind::Equal || obj0 != obj1))
        fail(e, "cannot compare an object with a number in '" + h + "'");
    } else if (h == "when") {
      fail(e, "'when' is only allowed in effects");
    } else if (!h.empty()) {
      auto p = d_.find_predicate(h);
      if (!p) fail(e, "unknown predicate '" + h + "'");
      c.kind = Condition::Kind::Atom;
      c.pred = *p;
      c.args = args_for(e, d_.predicates[*p].arg_types, "predicate '" + h + "'");
    } else {
      fail(e, "expected a condition");
    }
    return c;
  }

  Effect eff(const SExpr& e) {
    Nested guard(*this, e);
    Effect x;
    x.loc = e.loc;
    expect_list(e, "an effect");
    if (e.items.empty()) return x;  // empty conjunction
    const std::string& h = e.head();
    size_t n = e.items.size() - 1;
    if (h == "and") {
      for (size_t i = 1; i <= n; ++i) x.kids.push_back(eff(e.items[i]));
    } else if (h == "not") {
      if (n != 1) fail(e, "arity mismatch: 'not' takes 1 argument, given " + std::to_string(n));
      const SExpr& a = expect_list(e.items[1], "an atom to delete");
      Effect inner = eff(a);
      if (inner.kind != Effect::Kind::Add) fail(a, "only atoms can be negated in effects");
      inner.kind = Effect::Kind::Del;
      inner.loc = e.loc;
      return inner;
    } else if (h == "when") {
      if (n != 2) fail(e, "expected (when condition effect)");
      x.kind = Effect::Kind::When;
      x.cond = cond(e.items[1]);
      x.kids.push_back(eff(e.items[2]));
    } else if (h == "forall") {
      if (n != 2) fail(e, "expected (forall (variables) effect)");
      x.kind = Effect::Kind::Forall;
      open_vars(e.items[1], nullptr, &x);
      x.kids.push_back(eff(e.items[2]));
      close_vars(x.var_types.size());
    } else if (h == "assign" || h == "increase" || h == "decrease" || h == "scale-up" ||
               h == "scale-down") {
      if (n != 2) fail(e, "arity mismatch: '" + h + "' takes 2 arguments, given " + std::to_string(n));
      x.kind = h == "assign"     ? Effect::Kind::Assign
               : h == "increase" ? Effect::Kind::Increase
               : h == "decrease" ? Effect::Kind::Decrease
               : h == "scale-up" ? Effect::Kind::ScaleUp
                                 : Effect::Kind::ScaleDown;
      const SExpr& target = e.items[1];
      std::string fname = target.is_list ? target.head() : target.atom;
      auto f = d_.find_function(fname);
      if (!f) fail(target, "unknown function '" + fname + "'");
      x.func = *f;
      if (target.is_list) x.args = args_for(target, d_.functions[*f].arg_types, "function '" + fname + "'");
      else if (!d_.functions[*f].arg_types.empty()) fail(target, "arity mismatch: function '" + fname + "' needs arguments");
      x.value = num(e.items[2]);
    } else if (!h.empty()) {
      auto p = d_.find_predicate(h);
      if (!p) fail(e, "unknown predicate '" + h + "'");
      if (d_.predicates[*p].derived)
        fail(e, "predicate '" + h + "' is derived (:derived): it follows from the state, and effects may not change it");
      x.kind = Effect::Kind::Add;
      x.pred = *p;
      x.args = args_for(e, d_.predicates[*p].arg_types, "predicate '" + h + "'");
    } else {
      fail(e, "expected an effect");
    }
    return x;
  }

 private:
  const Domain& d_;
  const Problem* p_;
  int depth_ = 0;  // current num/cond/eff nesting
};

TypeId ensure_type(Domain& d, const std::string& name) {
  if (auto t = d.find_type(name)) return *t;
  d.types.push_back(TypeDef{name, 0, {}});
  return static_cast<TypeId>(d.types.size() - 1);
}

// Every type has at most one parent: "car - vehicle car - toy" is an error.
void parse_types(Domain& d, const SExpr& sec) {
  std::map<std::string, TypedName> declared;  // type -> its declaration with an explicit parent
  std::map<std::string, SourceLoc> named_as_parent;
  std::set<std::string> named_itself;
  for (auto& tn : typed_list(sec.items, 1, sec)) {
    named_itself.insert(tn.name);
    if (tn.type != "object") named_as_parent.emplace(tn.type, tn.type_loc);
    if (tn.type.rfind("(either", 0) == 0)
      fail(tn.type_loc, "type '" + tn.name + "' cannot have a union " + tn.type + " as its parent: name one type");
    if (tn.name == "object") {
      // The root type has no parent: "object - dish" would close a cycle.
      if (tn.type != "object") fail(tn.loc, "cyclic type hierarchy: the root type 'object' cannot be a subtype of '" + tn.type + "'");
      continue;
    }
    if (tn.type != "object") {
      auto [it, fresh] = declared.emplace(tn.name, tn);
      if (!fresh && it->second.type != tn.type)
        fail(tn.loc, "type '" + tn.name + "' is declared twice with two parents: '" + it->second.type + "' (line " +
                         std::to_string(it->second.loc.line) + ") and '" + tn.type + "'");
    }
    TypeId parent = ensure_type(d, tn.type);
    TypeId t = ensure_type(d, tn.name);
    if (d.is_subtype(parent, t)) fail(tn.loc, "cyclic type hierarchy at '" + tn.name + "'");
    if (tn.type != "object" || d.types[t].parent <= 0) d.types[t].parent = parent;
  }
  // A parent never declared itself ("car - vehicle" alone) is a type of its
  // own under object, as other planners read it; it is recorded, so the pack
  // layer can refuse a slip (`vehical`) and let the agents' type pass.
  for (const auto& [name, loc] : named_as_parent)
    if (!named_itself.count(name)) d.implicit_parents.emplace_back(name, loc);
}

// Adds the union types `(either a b)` the domain writes anywhere (parameters,
// predicates, quantifiers) to its type table, before anything reads them.
void declare_union_types(Domain& d, const SExpr& e) {
  if (!e.is_list) return;
  if (e.head() == "either") {
    const std::string name = either_name(e);
    if (d.find_type(name)) return;
    if (e.items.size() < 2) fail(e, "(either) names no type");
    TypeDef u{name, -1, {}};
    for (size_t i = 1; i < e.items.size(); ++i) {
      const SExpr& m = e.items[i];
      if (m.is_list) fail(m, "expected a type name in (either ...), found a list");
      auto t = d.find_type(m.atom);
      if (!t) fail(m, "unknown type '" + m.atom + "' in " + name);
      u.either.push_back(*t);
    }
    d.types.push_back(std::move(u));
    return;
  }
  for (const SExpr& k : e.items) declare_union_types(d, k);
}

TypeId type_of_name(const Domain& d, const TypedName& tn) {
  auto t = d.find_type(tn.type);
  if (!t) fail(tn.type_loc, tn.type.rfind("(either", 0) == 0 ? "unsupported: the union type " + tn.type + " here (the domain uses no such union)"
                                                          : "unknown type '" + tn.type + "'");
  return *t;
}

void parse_predicates(Domain& d, const SExpr& sec) {
  for (size_t i = 1; i < sec.items.size(); ++i) {
    const SExpr& p = expect_list(sec.items[i], "a predicate declaration");
    if (p.items.empty() || p.items[0].is_list) fail(p, "expected a predicate name");
    if (d.find_predicate(p.head())) fail(p, "predicate '" + p.head() + "' declared twice");
    PredicateDef def{p.head(), {}, p.loc};
    for (auto& tn : typed_list(p.items, 1, p)) def.arg_types.push_back(type_of_name(d, tn));
    d.predicates.push_back(def);
  }
}

void parse_functions(Domain& d, const SExpr& sec) {
  std::vector<FunctionDef> pending;
  auto flush = [&](ValueType vt) {
    for (auto& f : pending) {
      f.type = vt;
      d.functions.push_back(f);
    }
    pending.clear();
  };
  for (size_t i = 1; i < sec.items.size(); ++i) {
    const SExpr& it = sec.items[i];
    if (it.is_atom("-")) {
      if (i + 1 >= sec.items.size() || sec.items[i + 1].is_list) fail(it, "expected a function type after '-'");
      const std::string& t = sec.items[i + 1].atom;
      if (t == "number" || t == "integer" || t == "int") flush(ValueType::Int);
      else if (t == "bit-matrix" || t == "boolean-matrix") flush(ValueType::Matrix);
      else fail(sec.items[i + 1], "unsupported function type '" + t + "' (expected number, integer or bit-matrix)");
      ++i;
      continue;
    }
    const SExpr& f = expect_list(it, "a function declaration");
    if (f.items.empty() || f.items[0].is_list) fail(f, "expected a function name");
    if (d.find_function(f.head())) fail(f, "function '" + f.head() + "' declared twice");
    FunctionDef def{f.head(), {}, ValueType::Int, f.loc};
    for (auto& tn : typed_list(f.items, 1, f)) def.arg_types.push_back(type_of_name(d, tn));
    pending.push_back(def);
  }
  flush(ValueType::Int);
}

void parse_action(Domain& d, const SExpr& sec) {
  if (sec.items.size() < 2 || sec.items[1].is_list) fail(sec, "expected an action name after :action");
  ActionSchema a;
  a.name = sec.items[1].atom;
  a.loc = sec.loc;
  if (d.find_action(a.name) >= 0) fail(sec, "action '" + a.name + "' declared twice");
  ExprParser ep(d, nullptr);
  const SExpr* pre = nullptr;
  const SExpr* effect = nullptr;
  for (size_t i = 2; i < sec.items.size(); i += 2) {
    const SExpr& key = sec.items[i];
    if (key.is_list || i + 1 >= sec.items.size()) fail(key, "expected ':parameters', ':precondition' or ':effect' followed by a value");
    const SExpr& val = sec.items[i + 1];
    if (key.atom == ":parameters") {
      expect_list(val, "a parameter list");
      for (auto& tn : typed_list(val.items, 0, val)) {
        if (tn.name.empty() || tn.name[0] != '?') fail(tn.loc, "expected a parameter variable, found '" + tn.name + "'");
        if (std::find(a.param_names.begin(), a.param_names.end(), tn.name.substr(1)) != a.param_names.end())
          fail(tn.loc, "parameter '" + tn.name + "' of action '" + a.name + "' is declared twice");
        a.param_names.push_back(tn.name.substr(1));
        a.param_types.push_back(type_of_name(d, tn));
        ep.scope.vars.push_back({tn.name.substr(1), a.param_types.back()});
        ep.scope.visible.push_back(ep.scope.num_slots() - 1);
      }
    } else if (key.atom == ":precondition") {
      pre = &val;
    } else if (key.atom == ":effect") {
      effect = &val;
    } else {
      fail(key, "unknown action section '" + key.atom + "'");
    }
  }
  if (pre) a.precondition = ep.cond(*pre);
  if (effect) a.effect = ep.eff(*effect);
  a.num_vars = ep.scope.num_slots();
  d.actions.push_back(std::move(a));
}

// (:derived (p ?x - t ...) condition). The parameters' types default to the
// predicate's declared ones.
void parse_derived(Domain& d, const SExpr& sec) {
  if (sec.items.size() != 3 || !sec.items[1].is_list || sec.items[1].items.empty() || sec.items[1].items[0].is_list)
    fail(sec, "expected (:derived (predicate ?parameters) condition)");
  const SExpr& head = sec.items[1];
  auto pid = d.find_predicate(head.head());
  if (!pid) fail(head, "derived predicate '" + head.head() + "' is not declared in :predicates");
  DerivedRule r;
  r.pred = *pid;
  r.loc = sec.loc;
  const PredicateDef& pd = d.predicates[static_cast<size_t>(*pid)];
  auto params = typed_list(head.items, 1, head);
  if (params.size() != pd.arg_types.size())
    fail(head, "arity mismatch: predicate '" + pd.name + "' takes " + std::to_string(pd.arg_types.size()) +
                   " argument(s), its :derived rule gives " + std::to_string(params.size()));
  ExprParser ep(d, nullptr);
  for (size_t i = 0; i < params.size(); ++i) {
    const TypedName& tn = params[i];
    if (tn.name.empty() || tn.name[0] != '?') fail(tn.loc, "expected a parameter variable, found '" + tn.name + "'");
    if (std::find(r.param_names.begin(), r.param_names.end(), tn.name.substr(1)) != r.param_names.end())
      fail(tn.loc, "parameter '" + tn.name + "' of derived predicate '" + pd.name + "' is declared twice");
    TypeId t = tn.type == "object" ? pd.arg_types[i] : type_of_name(d, tn);
    r.param_names.push_back(tn.name.substr(1));
    r.param_types.push_back(t);
    ep.scope.vars.push_back({tn.name.substr(1), t});
    ep.scope.visible.push_back(ep.scope.num_slots() - 1);
  }
  r.body = ep.cond(sec.items[2]);
  r.num_vars = ep.scope.num_slots();
  d.derived.push_back(std::move(r));
}

// The linear form of a :metric expression: coefficient x ground fluent terms.
// Anything else (a product of fluents, a division) is refused.
void linear_terms(const Domain& d, const NumExpr& x, int64_t coef, std::vector<Metric::Term>& out, int64_t& constant) {
  using K = NumExpr::Kind;
  auto product = [&](int64_t a, int64_t b) {
    int64_t v = 0;
    if (__builtin_mul_overflow(a, b, &v)) fail(x.loc, "integer overflow in the :metric expression");
    return v;
  };
  switch (x.kind) {
    case K::Const: constant += product(coef, x.value); return;
    case K::Fluent: {
      Metric::Term t{coef, x.func, {}};
      for (const TermRef& a : x.args) t.args.push_back(a.index);
      out.push_back(std::move(t));
      return;
    }
    case K::Add: case K::Sub:
      linear_terms(d, x.kids[0], coef, out, constant);
      linear_terms(d, x.kids[1], x.kind == K::Add ? coef : product(coef, -1), out, constant);
      return;
    case K::Neg: linear_terms(d, x.kids[0], product(coef, -1), out, constant); return;
    case K::Mul: {
      // One side must be a constant (after its own linear form).
      for (int c = 0; c < 2; ++c) {
        std::vector<Metric::Term> probe;
        int64_t k = 0;
        linear_terms(d, x.kids[static_cast<size_t>(c)], 1, probe, k);
        if (probe.empty()) {
          linear_terms(d, x.kids[static_cast<size_t>(1 - c)], product(coef, k), out, constant);
          return;
        }
      }
      fail(x.loc, "the :metric multiplies two fluents: only a linear expression of fluents (sums of constant "
                  "multiples) can be minimised");
    }
    case K::Div: fail(x.loc, "division in the :metric is not supported: only sums of constant multiples of fluents");
    default: fail(x.loc, "the :metric must be a linear expression of fluents (e.g. (total-cost))");
  }
}

}  // namespace

// ---------------------------------------------------------------- Domain

Domain parse_domain(const std::string& text, const std::string& file) {
  auto top = read_pddl_forms(text, file);
  if (top.size() != 1 || !top[0].is_list || top[0].head() != "define")
    fail(top.empty() ? SourceLoc{file, 1, 1} : top[0].loc, "expected (define (domain NAME) ...)");
  const SExpr& def = top[0];
  Domain d;
  d.file = file;
  d.types.push_back(TypeDef{"object", -1, {}});
  if (def.items.size() < 2 || !def.items[1].is_list || def.items[1].head() != "domain" || def.items[1].items.size() != 2)
    fail(def, "expected (domain NAME) after define");
  d.name = def.items[1].items[1].atom;
  // Sections in any order, but types before their users: do two passes.
  for (size_t i = 2; i < def.items.size(); ++i) {
    const SExpr& sec = expect_list(def.items[i], "a domain section");
    const std::string& h = sec.head();
    if (h == ":requirements") {
      for (size_t j = 1; j < sec.items.size(); ++j) {
        const std::string& r = sec.items[j].atom;
        if (!kSupportedRequirements.count(r)) fail(sec.items[j], "unsupported requirement '" + r + "'");
        d.requirements.push_back(r);
      }
    } else if (h == ":types") {
      parse_types(d, sec);
    }
  }
  declare_union_types(d, def);
  for (size_t i = 2; i < def.items.size(); ++i) {
    const SExpr& sec = def.items[i];
    const std::string& h = sec.head();
    if (h == ":requirements" || h == ":types") continue;
    if (h == ":constants") {
      for (auto& tn : typed_list(sec.items, 1, sec)) {
        for (auto& c : d.constants)
          if (c.name == tn.name) fail(tn.loc, "constant '" + tn.name + "' declared twice");
        if (tn.type.rfind("(either", 0) == 0)
          fail(tn.type_loc, "constant '" + tn.name + "' has the union type " + tn.type + ": give each object one type");
        d.constants.push_back(ObjectDef{tn.name, type_of_name(d, tn), true});
      }
    } else if (h == ":predicates") {
      parse_predicates(d, sec);
    } else if (h == ":functions") {
      parse_functions(d, sec);
    } else if (h == ":action" || h == ":derived") {
      continue;  // after everything is declared
    } else {
      fail(sec, "unknown or unsupported domain section '" + h + "'");
    }
  }
  if (auto tc = d.find_function("total-cost"); tc && d.functions[*tc].arg_types.empty()) d.total_cost = *tc;
  // Derived predicates first: effects may not name them.
  for (size_t i = 2; i < def.items.size(); ++i)
    if (def.items[i].head() == ":derived") {
      const SExpr& head = def.items[i].items.size() > 1 ? def.items[i].items[1] : def.items[i];
      if (auto p = d.find_predicate(head.head())) d.predicates[static_cast<size_t>(*p)].derived = true;
    }
  for (size_t i = 2; i < def.items.size(); ++i)
    if (def.items[i].head() == ":derived") parse_derived(d, def.items[i]);
  for (size_t i = 2; i < def.items.size(); ++i)
    if (def.items[i].head() == ":action") parse_action(d, def.items[i]);
  return d;
}

Domain load_domain(const std::string& path) { return parse_domain(read_text_file(path), path); }

// ---------------------------------------------------------------- Problem

namespace {

// (:metric minimize <linear expression of ground fluents>); everything else
// is refused, so that no metric is silently ignored.
Metric parse_metric(const Domain& d, ExprParser& ep, const SExpr& sec) {
  if (sec.items.size() != 3 || sec.items[1].is_list)
    fail(sec, "expected (:metric minimize <expression>)");
  const std::string& dir = sec.items[1].atom;
  if (dir == "maximize")
    fail(sec.items[1], "(:metric maximize ...) is not supported: clips finds plans of least cost; write the metric "
                       "as minimize of a linear expression of fluents");
  if (dir != "minimize") fail(sec.items[1], "expected 'minimize' after :metric, found '" + dir + "'");
  const SExpr& e = sec.items[2];
  const std::string name = e.is_list ? e.head() : e.atom;
  if (name == "total-time" && !d.find_function(name))
    fail(e, "(:metric minimize (total-time)) is not supported: actions here have no durations (write (total-cost) "
            "and :action-costs, or leave the metric out to minimise the number of actions)");
  Metric m;
  m.loc = sec.loc;
  int64_t constant = 0;
  linear_terms(d, ep.num(e), 1, m.terms, constant);
  for (const Metric::Term& t : m.terms)
    if (d.functions[static_cast<size_t>(t.func)].type != ValueType::Int)
      fail(e, "the :metric reads the bit-matrix '" + d.functions[static_cast<size_t>(t.func)].name + "'");
  return m;
}

}  // namespace

Problem parse_problem(const Domain& d, const std::string& text, const std::string& file, bool with_goal) {
  auto top = read_pddl_forms(text, file);
  if (top.size() != 1 || !top[0].is_list || top[0].head() != "define")
    fail(top.empty() ? SourceLoc{file, 1, 1} : top[0].loc, "expected (define (problem NAME) ...)");
  const SExpr& def = top[0];
  Problem p;
  p.file = file;
  p.objects = d.constants;
  if (def.items.size() < 2 || !def.items[1].is_list || def.items[1].head() != "problem" || def.items[1].items.size() != 2)
    fail(def, "expected (problem NAME) after define");
  p.name = def.items[1].items[1].atom;
  for (size_t i = 2; i < def.items.size(); ++i) {
    const SExpr& sec = expect_list(def.items[i], "a problem section");
    if (sec.head() == ":domain") {
      if (sec.items.size() != 2 || sec.items[1].atom != d.name)
        fail(sec, "problem is for domain '" + (sec.items.size() > 1 ? sec.items[1].str() : std::string("?")) +
                      "' but the domain file defines '" + d.name + "'");
    } else if (sec.head() == ":objects") {
      for (auto& tn : typed_list(sec.items, 1, sec)) {
        if (p.find_object(tn.name)) fail(tn.loc, "object '" + tn.name + "' declared twice");
        if (tn.type.rfind("(either", 0) == 0)
          fail(tn.type_loc, "object '" + tn.name + "' has the union type " + tn.type + ": give each object one type");
        p.objects.push_back(ObjectDef{tn.name, type_of_name(d, tn), false});
      }
    }
  }
  ExprParser ep(d, &p);
  for (size_t i = 2; i < def.items.size(); ++i) {
    const SExpr& sec = def.items[i];
    const std::string& h = sec.head();
    if (h == ":domain" || h == ":objects") continue;
    if (h == ":init") {
      for (size_t j = 1; j < sec.items.size(); ++j) {
        const SExpr& f = expect_list(sec.items[j], "an initial fact");
        if (f.head() == "=") {
          if (f.items.size() != 3) fail(f, "expected (= (function args) value)");
          const SExpr& target = f.items[1];
          std::string fname = target.is_list ? target.head() : target.atom;
          auto fid = d.find_function(fname);
          if (!fid) fail(target, "unknown function '" + fname + "'");
          InitFluent in{*fid, {}, {}, f.loc};
          if (target.is_list) {
            for (auto& r : ep.args_for(target, d.functions[*fid].arg_types, "function '" + fname + "'"))
              in.args.push_back(r.index);
          } else if (!d.functions[*fid].arg_types.empty()) {
            fail(target, "arity mismatch: function '" + fname + "' needs arguments");
          }
          in.value = ep.num(f.items[2]);
          p.init_fluents.push_back(std::move(in));
        } else if (f.head() == "not") {
          continue;  // closed world: negative facts are the default
        } else {
          auto pid = d.find_predicate(f.head());
          if (!pid) fail(f, "unknown predicate '" + f.head() + "'");
          if (d.predicates[static_cast<size_t>(*pid)].derived)
            fail(f, "predicate '" + f.head() + "' is derived (:derived): it follows from the other facts and "
                    "cannot be stated in :init");
          InitAtom a{*pid, {}, f.loc};
          for (auto& r : ep.args_for(f, d.predicates[*pid].arg_types, "predicate '" + f.head() + "'"))
            a.args.push_back(r.index);
          p.init_atoms.push_back(std::move(a));
        }
      }
    } else if (h == ":goal") {
      if (sec.items.size() != 2) fail(sec, "expected (:goal condition)");
      p.goal_sexpr = sec.items[1];
      if (with_goal) {
        p.goal = ep.cond(sec.items[1]);
        p.goal_num_vars = ep.scope.num_slots();
      }
    } else if (h == ":metric") {
      p.metric = parse_metric(d, ep, sec);
    } else {
      fail(sec, "unknown or unsupported problem section '" + h + "'");
    }
  }
  return p;
}

Problem load_problem(const Domain& d, const std::string& path, bool with_goal) {
  return parse_problem(d, read_text_file(path), path, with_goal);
}

Condition parse_condition(const Domain& d, const Problem& p, const SExpr& e, int* num_vars) {
  ExprParser ep(d, &p);
  Condition c = ep.cond(e);
  if (num_vars) *num_vars = ep.scope.num_slots();
  return c;
}

Condition parse_condition_text(const Domain& d, const Problem& p, const std::string& text,
                               const std::string& label, int* num_vars) {
  return parse_condition(d, p, read_one_sexpr(text, label), num_vars);
}

// ---------------------------------------------------------------- Printing

namespace {

struct Printer {
  const Domain& d;
  const Problem& p;
  std::vector<std::string> names;
  const std::vector<ObjectId>* binding;

  std::string term(const TermRef& t) const {
    if (!t.is_var) return p.objects[t.index].name;
    if (binding && t.index < static_cast<int>(binding->size()) && (*binding)[t.index] >= 0)
      return p.objects[(*binding)[t.index]].name;
    return "?" + (t.index < static_cast<int>(names.size()) ? names[t.index] : std::to_string(t.index));
  }
  std::string num(const NumExpr& x) const {
    using K = NumExpr::Kind;
    auto kids = [&](const char* op) {
      std::string s = std::string("(") + op;
      for (auto& k : x.kids) s += " " + num(k);
      return s + ")";
    };
    switch (x.kind) {
      case K::Const: return x.boolean ? (x.value ? "true" : "false") : std::to_string(x.value);
      case K::Object: return term(x.args[0]);
      case K::Fluent: {
        if (x.args.empty()) return d.functions[x.func].name;
        std::string s = "(" + d.functions[x.func].name;
        for (auto& a : x.args) s += " " + term(a);
        return s + ")";
      }
      case K::Add: return kids("+");
      case K::Sub: case K::Neg: return kids("-");
      case K::Mul: return kids("*");
      case K::Div: return kids("/");
      case K::NewMatrix: return kids("new-bit-matrix");
      case K::SetIndex: return kids("set-index");
      case K::GetIndex: return kids("get-index");
      case K::Width: return kids("width");
      case K::Height: return kids("height");
    }
    return "?";
  }
  std::string cond(const Condition& c) {
    using K = Condition::Kind;
    auto list = [&](const char* op) {
      std::string s = std::string("(") + op;
      for (auto& k : c.kids) s += " " + cond(k);
      return s + ")";
    };
    auto cmp = [&](const char* op) { return std::string("(") + op + " " + num(c.nums[0]) + " " + num(c.nums[1]) + ")"; };
    switch (c.kind) {
      case K::True: return "(and)";
      case K::False: return "(or)";
      case K::Atom: {
        std::string s = "(" + d.predicates[c.pred].name;
        for (auto& a : c.args) s += " " + term(a);
        return s + ")";
      }
      case K::Not: return list("not");
      case K::And: return list("and");
      case K::Or: return list("or");
      case K::Imply: return list("imply");
      case K::Exists: case K::Forall: {
        for (size_t i = 0; i < c.var_names.size(); ++i) {
          size_t slot = c.first_var + i;
          if (names.size() <= slot) names.resize(slot + 1);
          names[slot] = c.var_names[i];
        }
        std::string s = c.kind == K::Exists ? "(exists (" : "(forall (";
        for (size_t i = 0; i < c.var_names.size(); ++i) {
          if (i) s += " ";
          s += "?" + c.var_names[i] + " - " + d.types[c.var_types[i]].name;
        }
        // Quantified variables are never bound by the caller's binding.
        auto saved = binding;
        std::vector<ObjectId> masked;
        if (binding) {
          masked = *binding;
          for (size_t i = 0; i < c.var_names.size(); ++i)
            if (c.first_var + i < masked.size()) masked[c.first_var + i] = -1;
          binding = &masked;
        }
        s += ") " + cond(c.kids[0]) + ")";
        binding = saved;
        return s;
      }
      case K::Equal: return cmp("=");
      case K::Less: return cmp("<");
      case K::LessEq: return cmp("<=");
      case K::Greater: return cmp(">");
      case K::GreaterEq: return cmp(">=");
    }
    return "?";
  }
};

}  // namespace

std::string to_pddl(const Domain& d, const Problem& p, const Condition& c,
                    const std::vector<std::string>& var_names, const std::vector<ObjectId>* binding) {
  Printer pr{d, p, var_names, binding};
  return pr.cond(c);
}

}  // namespace clips::pddl
