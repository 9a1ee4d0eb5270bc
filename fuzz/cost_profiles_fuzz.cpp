// A pack's "cost_profiles" (issue 61). The input is the array's JSON text,
// spliced into a pack for the fetch domain (fuzz/fetch_domain.hpp) with its
// default roles. A pack the checks accept has at most 32 profiles a rule, a
// name each profile answers to, and prices every ground action of the fetch
// problem finitely, from 0 to 1e6, under each profile and its alone twin.
// (200 profiles, or costs that overflow the Boltzmann policies, used to run
// for minutes or poison every posterior.)
#include <cmath>
#include <memory>

#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "fuzz/fetch_domain.hpp"
#include "fuzz/fuzz_target.hpp"
#include "model/spec.hpp"

namespace {

constexpr size_t kMaxInputBytes = 8192;
constexpr size_t kMaxProfiles = 32;
constexpr double kMaxCost = 1e6;

}  // namespace

CLIPS_FUZZ_TARGET(cost_profiles) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const pddl::Task& task = fuzz::fetch_task();
  // The task shared as the specifications hold it (never freed: a static).
  static const std::shared_ptr<const pddl::Task> shared(&task, [](const pddl::Task*) {});
  const std::string text = R"({"domain": "fetch", "roles": {"noop_action": "wait"},)"
                           R"( "inference": {"alone_cost_factor": 2}, "cost_profiles": )" +
                           fuzz::as_text(data, size) + "}";
  try {
    const domains::PackPtr pack = domains::pack_for_domain(domains::parse_pack_spec(text, "<pack.json>"), task.domain());
    for (const domains::ProfileRule& rule : pack->spec().cost_profiles) {
      if (rule.profiles.size() > kMaxProfiles) __builtin_trap();
      for (const model::CostProfile& p : pack->profiles_for(rule.tag).profiles) {
        const model::Specification spec(shared, "(done plank1)", p);
        for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
          const double c = spec.cost(a);
          // The alone twins scale the assistant's costs by 2.
          if (!std::isfinite(c) || c < 0 || c > 2 * kMaxCost) __builtin_trap();
        }
      }
      for (const model::CostProfile& p : rule.profiles)
        if (pack->cost_profile(p.name).name != p.name) __builtin_trap();
    }
  } catch (const InputError&) {
  }
  return 0;
}
