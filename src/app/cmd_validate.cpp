// `clips validate`: simulate every observed plan and its completion, and check
// that the completion reaches exactly the dataset's true goal; then rehearse
// `clips bench` on the first plan that checks (every method's set-up, with tiny
// budgets), so that what bench would stop at is reported before it starts.
#include <fmt/core.h>

#include <set>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "data/dataset.hpp"
#include "data/validate.hpp"
#include "eval/experiment.hpp"

namespace clips::app {

namespace {

// The first evaluated plan (what bench runs) that checks.
const data::PlanRecord* first_checked_plan(const data::Dataset& ds, const data::ValidationReport& report) {
  for (const auto& r : report.results) {
    if (!r.ok) continue;
    for (const auto& p : ds.plans())
      if (p.id == r.plan_id && p.evaluated) return &p;
  }
  return nullptr;
}

}  // namespace

void register_validate(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Simulate every observed plan and its completion; check the true goals; rehearse clips bench on one plan");
  auto dataset = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto plans_only = std::make_shared<bool>(false);
  auto lm = std::make_shared<LmFlags>();
  add_dataset_option(cmd, *dataset, "Dataset directory (with domain.pddl, problems/, plans/)");
  cmd->add_flag("-q,--quiet", *quiet, "Print only failures, warnings and the final lines");
  cmd->add_flag("--plans-only", *plans_only,
                "Check the plans only; skip the rehearsal of clips bench (every method's set-up on the first plan "
                "that checks, with tiny search budgets)");
  add_lm_options(cmd, *lm);
  cmd->callback([=] {
    auto ds = data::Dataset::load(dataset_dir(*dataset));
    auto report = data::validate_dataset(ds);
    for (auto& r : report.results) {
      if (r.ok) {
        if (!*quiet) fmt::print("ok    {:<22} T={:<3} completion={:<3} goal={}\n", r.plan_id, r.observed_steps, r.completed_steps, r.goal);
      } else {
        fmt::print("FAIL  {:<22} {}\n", r.plan_id, r.error);
      }
    }
    fmt::print("validated {} plans, {} failed\n", report.results.size(), report.failed);
    int bench_failures = 0;
    if (!*plans_only) {
      if (const data::PlanRecord* plan = first_checked_plan(ds, report)) {
        eval::BenchCheck check;
        try {
          auto model = make_lm(*lm, ds);
          check = eval::check_bench_setup(ds, *plan, *model, eval::ExperimentOptions{});
        } catch (const std::exception& e) {
          // The language model itself (its corpus files, the endpoint).
          check.plan_id = plan->id;
          check.failures.push_back({"language model", e.what()});
        }
        for (const auto& m : check.passed)
          if (!*quiet) fmt::print("ok    bench set-up: {:<16} on plan {}\n", m, check.plan_id);
        for (const auto& w : check.warnings) fmt::print("WARN  bench set-up: {}\n", w);
        for (const auto& [what, error] : check.failures) fmt::print("FAIL  bench set-up: {}: {}\n", what, error);
        bench_failures = static_cast<int>(check.failures.size());
        fmt::print("bench set-up on plan {}: {} methods ok, {} failed, {} warnings\n", check.plan_id,
                   check.passed.size(), bench_failures, check.warnings.size());
      } else {
        fmt::print("bench set-up not checked: no plan bench would evaluate checks\n");
      }
    }
    g_exit_code = report.failed == 0 && bench_failures == 0 ? kExitOk : kExitSomeFailed;
  });
}

}  // namespace clips::app
