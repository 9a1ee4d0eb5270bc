#pragma once
// PDDL parser: text -> typed lifted AST (ast.hpp), with errors that name
// file:line:col and what was expected (unknown type/object/predicate/action,
// arity mismatch, unbalanced parentheses, unsupported requirement, ...).
//
// Supported: :strips :typing :negative-preconditions :disjunctive-preconditions
// :equality :existential-/universal-/quantified-preconditions
// :conditional-effects :adl :fluents :numeric-fluents :object-fluents(no)
// :action-costs, integer fluents, and the bit-matrix theory used by the
// Doors-Keys-Gems walls (new-bit-matrix, set-index, get-index, width, height).
#include <string>
#include <utility>
#include <vector>

#include "pddl/ast.hpp"
#include "pddl/sexpr.hpp"

namespace clips::pddl {

Domain parse_domain(const std::string& text, const std::string& file);
Domain load_domain(const std::string& path);
// `with_goal = false` keeps the :goal unparsed (goal_sexpr only): datasets whose
// problem goals are placeholders, sometimes ill-typed, load without errors.
Problem parse_problem(const Domain& domain, const std::string& text, const std::string& file,
                      bool with_goal = true);
Problem load_problem(const Domain& domain, const std::string& path, bool with_goal = true);

// A variable scope for parsing free-standing conditions (e.g. goals given on the
// command line). `num_vars` receives the number of variable slots used.
Condition parse_condition(const Domain& domain, const Problem& problem, const SExpr& e,
                          int* num_vars);
Condition parse_condition_text(const Domain& domain, const Problem& problem,
                               const std::string& text, const std::string& label, int* num_vars);

// Printing lifted conditions back to PDDL, with variables shown by the names
// in `var_names` (or substituted by `binding` objects when given).
std::string to_pddl(const Domain& d, const Problem& p, const Condition& c,
                    const std::vector<std::string>& var_names,
                    const std::vector<ObjectId>* binding = nullptr);

}  // namespace clips::pddl
