#pragma once
// The assistance set-up every front end starts from (bench, the session API,
// the server): the pack's roles, no-op cost and assistance rule, and the
// belief's state, step and search graph. Front ends add only what is theirs
// (budgets, the completed plan of a benchmark).
#include <memory>
#include <optional>

#include "assist/assist.hpp"
#include "domains/pack.hpp"
#include "inference/belief.hpp"

namespace clips::assist {

// `rule`: the pack's assistance_rule when not given.
AssistSetup setup_for(const domains::Pack& pack, std::shared_ptr<const pddl::Task> task,
                      const inference::Belief& belief, std::optional<AssistRule> rule = std::nullopt);

}  // namespace clips::assist
