#pragma once
// Typed, lifted PDDL: what the parser produces and the grounder consumes.
//
//   Domain  = types (a forest under `object`, plus `(either t1 t2)` unions),
//             constants, predicates, functions, derived predicates' rules
//             (:derived), action schemas (parameters, precondition, effect).
//   Problem = objects, initial facts and fluent assignments, goal, metric.
//
// Conditions, numeric expressions and effects are small trees of value nodes.
// Terms inside them are either variables (index into the enclosing scope's
// variable list) or objects (index into the task's object table), resolved
// by the parser so that the grounder never looks at names again.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pddl/sexpr.hpp"
#include "util/error.hpp"

namespace clips::pddl {

using TypeId = int;
using ObjectId = int;
using PredId = int;
using FuncId = int;

struct TermRef {
  bool is_var = false;
  int index = 0;  // variable slot or ObjectId
};

enum class ValueType { Int, Bool, Matrix };

struct NumExpr {
  enum class Kind {
    Const,       // integer literal, or true/false as 1/0
    Fluent,      // (f t1 .. tn)
    Object,      // an object or variable used as a value: only valid in `=`
    Add, Sub, Mul, Div, Neg,
    NewMatrix,   // (new-bit-matrix <bool> rows cols)
    SetIndex,    // (set-index m <bool> row col)
    GetIndex,    // (get-index m row col)  -> Bool (0/1)
    Width, Height,
  };
  Kind kind = Kind::Const;
  int64_t value = 0;            // Const
  bool boolean = false;         // Const written as true/false
  FuncId func = -1;             // Fluent
  std::vector<TermRef> args;    // Fluent args; Object uses args[0]
  std::vector<NumExpr> kids;    // operands
  SourceLoc loc;
};

struct Condition {
  enum class Kind { True, False, Atom, Not, And, Or, Imply, Exists, Forall, Equal, Less, LessEq, Greater, GreaterEq };
  Kind kind = Kind::True;
  PredId pred = -1;             // Atom
  std::vector<TermRef> args;    // Atom
  std::vector<Condition> kids;  // Not/And/Or/Imply/quantifier body (kids[0])
  std::vector<NumExpr> nums;    // comparisons (2 operands)
  std::vector<TypeId> var_types;  // quantifiers: types of the new variables
  std::vector<std::string> var_names;  // quantifiers: names without '?'
  int first_var = 0;            // quantifiers: slot of the first new variable
  SourceLoc loc;
};

struct Effect {
  enum class Kind { And, Add, Del, Assign, Increase, Decrease, ScaleUp, ScaleDown, When, Forall };
  Kind kind = Kind::And;
  PredId pred = -1;             // Add/Del
  FuncId func = -1;             // numeric
  std::vector<TermRef> args;    // atom or fluent args
  NumExpr value;                // numeric right-hand side
  Condition cond;               // When
  std::vector<Effect> kids;     // And / When (kids[0]) / Forall body (kids[0])
  std::vector<TypeId> var_types;  // Forall
  int first_var = 0;
  SourceLoc loc;
};

struct TypeDef {
  std::string name;     // "(either a b)" for a union
  TypeId parent = -1;   // -1 only for `object` and unions
  std::vector<TypeId> either;  // a union's member types; empty for a named type
};

struct PredicateDef {
  std::string name;
  std::vector<TypeId> arg_types;
  SourceLoc loc;
  bool derived = false;  // defined by :derived rules, never by effects or :init
};

// (:derived (p ?x - t) condition): p holds of objects exactly when the
// condition of one of its rules holds of them (rules of one predicate add up).
struct DerivedRule {
  PredId pred = -1;
  std::vector<std::string> param_names;  // without '?'
  std::vector<TypeId> param_types;
  Condition body;
  int num_vars = 0;  // parameters + quantified variables of the body
  SourceLoc loc;
};

struct FunctionDef {
  std::string name;
  std::vector<TypeId> arg_types;
  ValueType type = ValueType::Int;
  SourceLoc loc;
};

struct ActionSchema {
  std::string name;
  std::vector<std::string> param_names;  // without '?'
  std::vector<TypeId> param_types;
  std::optional<Condition> precondition;
  Effect effect;
  int num_vars = 0;  // parameters + every quantified variable, for binding arrays
  SourceLoc loc;
};

struct ObjectDef {
  std::string name;
  TypeId type = 0;
  bool is_constant = false;  // declared in the domain
};

struct Domain {
  std::string name;
  std::string file;
  std::vector<std::string> requirements;
  std::vector<TypeDef> types;  // types[0] is `object`
  std::vector<ObjectDef> constants;
  std::vector<PredicateDef> predicates;
  std::vector<FunctionDef> functions;
  std::vector<ActionSchema> actions;
  std::vector<DerivedRule> derived;
  std::optional<FuncId> total_cost;  // (total-cost) when :action-costs is used
  // Types named only as a parent (`car - vehicle`, no `vehicle` of its own),
  // where first named: the parser makes each a type under object, and the
  // pack layer decides whether that is the agents' type or a slip.
  std::vector<std::pair<std::string, SourceLoc>> implicit_parents;

  std::optional<TypeId> find_type(const std::string& n) const;
  std::optional<PredId> find_predicate(const std::string& n) const;
  std::optional<FuncId> find_function(const std::string& n) const;
  int find_action(const std::string& n) const;  // -1 if absent
  bool is_subtype(TypeId t, TypeId ancestor) const;
};

struct InitFluent {
  FuncId func;
  std::vector<ObjectId> args;
  NumExpr value;  // evaluated in order (later lines may read earlier values)
  SourceLoc loc;
};

struct InitAtom {
  PredId pred;
  std::vector<ObjectId> args;
  SourceLoc loc;
};

// (:metric minimize <linear expression of ground fluents>): plans cost the
// sum of coef x (the fluent's change) over their actions; the constant part
// of the expression (and the fluents' initial values) is the same for every
// plan and left out.
struct Metric {
  struct Term {
    int64_t coef = 1;
    FuncId func = -1;
    std::vector<ObjectId> args;
  };
  std::vector<Term> terms;
  SourceLoc loc;
};

struct Problem {
  std::string name;
  std::string file;
  std::vector<ObjectDef> objects;  // domain constants first, then problem objects
  std::vector<InitAtom> init_atoms;
  std::vector<InitFluent> init_fluents;
  std::optional<Condition> goal;   // absent when parsing was skipped
  int goal_num_vars = 0;
  std::optional<SExpr> goal_sexpr; // the :goal text as read, always kept
  std::optional<Metric> metric;

  std::optional<ObjectId> find_object(const std::string& n) const;
};

}  // namespace clips::pddl
