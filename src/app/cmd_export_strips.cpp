// `clips export-strips`: write a dataset problem (any pack) as a plain-STRIPS
// domain + problem with integer action costs, for external classical planners
// (Fast Downward: see docs/cli.md, "Exporting STRIPS").
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "app/cli.hpp"
#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "pddl/plan.hpp"

namespace clips::app {

namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw InputError("cannot write " + path.string() + " (is the directory writable?)");
  f << text;
  f.close();
  if (!f) throw InputError("error while writing " + path.string());
}

}  // namespace

void register_export_strips(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export-strips", "Export a problem as plain STRIPS with integer action costs (for Fast Downward etc.)");
  struct Opts {
    std::string dataset, problem, goal, costs, out, from_plan;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (with domain.pddl and problems/)");
  cmd->add_option("--problem", o->problem, "Problem id in the dataset (e.g. 2); optional with --from-plan");
  cmd->add_option("--goal", o->goal,
                  "Goal, e.g. \"(made table)\"; doors-keys-gems: a conjunction of (has <agent> <item>) atoms, e.g. "
                  "\"(has human gem2)\"")
      ->required();
  cmd->add_option("--costs", o->costs,
                  "Cost profile: a name of the pack's (doors-keys-gems: 1..4, C1..C4), 'unit' or 'task' (default: the "
                  "pack's default profile, else 'task' for domains with total-cost, else 'unit'; doors-keys-gems: C1)");
  cmd->add_option("--out", o->out, "Output directory (created if missing): domain.pddl, problem.pddl, export.json")
      ->required();
  cmd->add_option("--from-plan", o->from_plan, "Start from the end of this observed plan (dataset plan id)");
  cmd->callback([o] {
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    std::string problem = o->problem;
    std::shared_ptr<const pddl::Task> task;
    pddl::State start;
    if (!o->from_plan.empty()) {
      const auto& p = ds.plan(o->from_plan);
      if (!problem.empty() && problem != p.problem_id)
        throw InputError("plan " + p.id + " is on problem " + p.problem_id + ", not " + problem);
      problem = p.problem_id;
      task = ds.task(problem);
      start = pddl::simulate(*task, task->initial_state(), p.observed).states.back();
    } else {
      if (problem.empty()) throw InputError("--problem or --from-plan is required");
      task = ds.task(problem);
      start = task->initial_state();
    }
    std::string costs = o->costs;
    if (costs.empty())
      costs = !ds.pack().spec().default_cost_profile.empty() ? ds.pack().spec().default_cost_profile
              : task->domain().total_cost                    ? "task"
                                                              : "unit";
    auto profile = ds.pack().cost_profile(costs);
    auto exported = ds.pack().export_strips(*task, start, o->goal, profile);
    if (!exported)
      throw InputError("export-strips: the " + ds.pack().name() + " pack cannot compile its tasks to STRIPS");
    const domains::StripsExport& ex = *exported;

    namespace fs = std::filesystem;
    fs::path dir(o->out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError("cannot create output directory " + dir.string() + ": " + ec.message());
    if (!fs::is_directory(dir)) throw InputError(dir.string() + " exists and is not a directory");
    nlohmann::json meta;
    meta["cost_scale"] = ex.cost_scale;
    meta["source_problem"] = problem;
    meta["goal"] = o->goal;
    meta["costs"] = profile.name;
    if (!o->from_plan.empty()) meta["from_plan"] = o->from_plan;
    if (!ex.original_actions.empty()) meta["actions"] = ex.original_actions;
    write_file(dir / "domain.pddl", ex.domain);
    write_file(dir / "problem.pddl", ex.problem);
    write_file(dir / "export.json", meta.dump(2) + "\n");
    fmt::print(stderr, "wrote {}/domain.pddl, problem.pddl, export.json (costs {} scaled by {})\n", dir.string(), profile.name,
               ex.cost_scale);
    g_exit_code = 0;
  });
}

}  // namespace clips::app
