// `clips validate`: simulate every observed plan and its completion, and check
// that the completion reaches exactly the dataset's true goal.
#include <fmt/core.h>

#include <set>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "data/dataset.hpp"
#include "data/validate.hpp"

namespace clips::app {

void register_validate(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "Simulate every observed plan and its completion; check the true goals");
  auto dataset = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  add_dataset_option(cmd, *dataset, "Dataset directory (with domain.pddl, problems/, plans/)");
  cmd->add_flag("-q,--quiet", *quiet, "Print only failures and the final line");
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
    g_exit_code = report.failed == 0 ? kExitOk : kExitSomeFailed;
  });
}

}  // namespace clips::app
