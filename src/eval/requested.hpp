#pragma once
// Whether an assistance episode did what the instruction explicitly asked of
// the assistant (data::PlanRecord::requested, from instructions.tsv).
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "pddl/task.hpp"

namespace clips::eval {

// A requested atom: its bit in the task and whether it is to become true
// (false: `(not ...)`, to become false).
struct RequestedAtom {
  int bit = -1;
  bool positive = true;
};

// The atoms of `text` ("(holding human can1) (not (locked shed))"), each a
// dynamic atom of `task`; InputError naming `where` (file and plan) for
// anything else.
std::vector<RequestedAtom> parse_requested(const pddl::Task& task, const std::string& text, const std::string& where);

// "<dataset>/instructions.tsv, plan <id>": where a plan's requested atoms come from.
std::string requested_where(const data::Dataset& ds, const data::PlanRecord& p);

// Whether every atom is made so (made true, or false for a negated one) by
// an action of `assistant`, running `actions` from `start`. nullopt when
// nothing was requested. The run stops at an action not applicable (what
// it has done so far counts).
std::optional<bool> request_done(const pddl::Task& task, const pddl::State& start, pddl::ObjectId assistant,
                                 const std::vector<RequestedAtom>& atoms, const std::vector<pddl::ActionId>& actions);

}  // namespace clips::eval
