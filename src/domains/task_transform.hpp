#pragma once
// Task transformations: what clips adds to a user's domain and problems
// before grounding, so that a domain needs none of the machinery only clips
// uses (docs/domains.md, "What clips adds to your domain").
//
//   Freezing. clips freezes an agent in some simulations by setting
//     (frozen agent) (model::freeze). A domain without a `frozen` predicate
//     gets (frozen ?a - <agent type>) and (not (frozen ?a)) in the
//     precondition of every action except the pack's no-op, ?a the action's
//     acting agent (its first parameter).
//   Turns. The agents act in turns. Unless the domain writes the turn idiom
//     itself (roles.turns "domain", the default when it declares the turn
//     predicate), clips adds the turn predicate (roles.turn_predicate) and
//     next-turn, (<turn> ?a) at the front of every precondition, the hand-over
//     (not (<turn> ?a)) (forall (?b - <agent type>) (when (next-turn ?a ?b)
//     (<turn> ?b))) to every effect, the no-op (<noop> ?a - <agent type>) when
//     the domain lacks it, and to every problem (<turn> first) and the
//     next-turn cycle of the turn order (roles.turns: "alternate" = principal,
//     assistant; or an explicit array of agent names).
//
// A domain that declares `frozen` and its turn predicate (both paper domains,
// the workshop) is left exactly as parsed, so its grounding is unchanged. The
// generic pack (no pack file) adds nothing. The transformation works on the
// parsed AST (pddl::Domain / pddl::Problem), between parsing and grounding.
#include <memory>

#include "domains/pack.hpp"
#include "pddl/ast.hpp"

namespace clips::domains {

// What to add for `spec` to the parsed `domain`, and the checks that needs
// (InputError naming the pack field, or the action and its file:line): the
// agent type exists, every action's first parameter is of it, roles.turns
// fits the domain, the no-op takes one agent.
TaskTransform plan_task_transform(const PackSpec& spec, const pddl::Domain& domain);

// The domain with spec.transform applied (a copy), or `domain` itself when
// the transform is empty or `domain` is already prepared.
std::shared_ptr<const pddl::Domain> prepare_domain(const PackSpec& spec, std::shared_ptr<const pddl::Domain> domain);
// Whether `domain` has what spec.transform adds (true when it adds nothing).
bool is_prepared(const PackSpec& spec, const pddl::Domain& domain);

// A problem parsed against prepare_domain's result, before grounding: checks
// that the roles name objects of the problem (a declared pack) and, when
// turns are compiled, adds the turn facts. InputError naming the problem
// file and the pack field.
void prepare_problem(const PackSpec& spec, const pddl::Domain& domain, pddl::Problem& problem);

}  // namespace clips::domains
