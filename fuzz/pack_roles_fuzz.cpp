// A pack's "roles" block (issue 61). The input is the block's JSON text,
// spliced into a pack for the fetch domain (fuzz/fetch_domain.hpp); the pack
// is checked against the domain, the domain and the problem prepared for it
// (turns compiled in or not) and the problem grounded. A pack the checks
// accept must name agents that act: the principal and the assistant are
// objects some ground action takes as its agent, the no-op takes one
// argument, and every profile of the pack prices every action finitely.
// ("roles.noop_action" naming a two-parameter action and "roles.principal"
// naming a room were accepted, and silently changed every posterior.)
#include <cmath>
#include <memory>

#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "domains/task_transform.hpp"
#include "fuzz/fetch_domain.hpp"
#include "fuzz/fuzz_target.hpp"
#include "model/spec.hpp"

namespace {

constexpr size_t kMaxInputBytes = 4096;

bool acts(const clips::pddl::Task& task, const std::string& agent) {
  for (clips::pddl::ActionId a = 0; a < task.num_actions(); ++a) {
    const auto& args = task.action(a).args;
    if (!args.empty() && task.object_name(args[0]) == agent) return true;
  }
  return false;
}

}  // namespace

CLIPS_FUZZ_TARGET(pack_roles) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const pddl::Task& fetch = fuzz::fetch_task();
  const std::string text = R"({"domain": "fetch", "roles": )" + fuzz::as_text(data, size) + "}";
  try {
    domains::PackSpec spec = domains::parse_pack_spec(text, "<pack.json>");
    const domains::PackPtr pack = domains::pack_for_domain(std::move(spec), fetch.domain());
    const auto domain = domains::prepare_domain(
        pack->spec(), std::make_shared<const pddl::Domain>(pddl::parse_domain(fuzz::kFetchDomain, "<fetch domain>")));
    auto problem = std::make_shared<pddl::Problem>(pddl::parse_problem(*domain, fuzz::kFetchProblem, "<fetch>"));
    domains::prepare_problem(pack->spec(), *domain, *problem);
    const auto grounded = std::make_shared<const pddl::Task>(domain, problem);
    const pddl::Task& task = *grounded;
    const domains::Roles& roles = pack->spec().roles;
    if (!acts(task, roles.principal) || !acts(task, roles.assistant)) __builtin_trap();
    const int noop = task.domain().find_action(roles.noop_action);
    if (noop >= 0 && task.domain().actions[static_cast<size_t>(noop)].param_types.size() != 1) __builtin_trap();
    for (const model::CostProfile& profile : pack->profiles_for("").profiles) {
      const model::Specification spec(grounded, "(done plank1)", profile);
      for (pddl::ActionId a = 0; a < task.num_actions(); ++a)
        if (!std::isfinite(spec.cost(a)) || spec.cost(a) < 0) __builtin_trap();
    }
    (void)task.applicable_actions(task.initial_state());
  } catch (const InputError&) {
  }
  return 0;
}
