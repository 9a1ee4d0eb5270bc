// `clips validate`: simulate every observed plan and its completion, and check
// that the completion reaches exactly the dataset's true goal; then rehearse
// `clips bench` on the first plan that checks (every method's set-up, with tiny
// budgets), so that what bench would stop at is reported before it starts.
#include <fmt/core.h>

#include <filesystem>
#include <set>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "data/dataset.hpp"
#include "data/validate.hpp"
#include "domains/pack.hpp"
#include "language/listener.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "pddl/sexpr.hpp"
#include "util/program_name.hpp"
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

// The dataset's own pack.json against data/schema/pack.schema.json (the C++
// reader checks it again, and more, when the dataset loads). The number of
// violations, each printed as a FAIL line.
int check_pack_schema(const std::string& dir, bool quiet) {
  const std::filesystem::path file = std::filesystem::path(dir) / "pack.json";
  if (!std::filesystem::exists(file)) return 0;
  std::vector<std::string> errors;
  try {
    errors = domains::pack_schema_errors(pddl::read_text_file(file.string()), file.string());
  } catch (const InputError& e) {
    // Not JSON (the dataset's load reports it), or no schema to check against.
    fmt::print("WARN  {}: not checked against the schema {}: {}\n", file.string(), domains::pack_schema_path(), e.what());
    return 0;
  }
  for (const auto& e : errors) fmt::print("FAIL  {}: {}\n", file.string(), e);
  if (errors.empty() && !quiet) fmt::print("ok    {} conforms to {}\n", file.string(), domains::pack_schema_path());
  return static_cast<int>(errors.size());
}

// What the pack left to clips and clips found from the domain: the goal
// atoms of salient actions without `goal_atoms`, where each salient action
// leaves its focal object (language.destinations), the salient actions whose
// focal object is a place and so is named in commands, and the WordNet senses
// the generated corpus gives type names whose first sense is not the domain's.
void print_derived(const data::Dataset& ds) {
  const domains::PackSpec& spec = ds.pack().spec();
  for (const std::string& action : spec.derived_goal_atoms) {
    std::string atoms;
    if (auto it = spec.language.goal_atoms.find(action); it != spec.language.goal_atoms.end())
      for (const std::string& a : it->second) atoms += (atoms.empty() ? "" : " ") + a;
    fmt::print("ok    derived from the effects: {} means {}\n", action, atoms.empty() ? "nothing" : atoms);
  }
  for (const auto& r : spec.language.salient_actions)
    if (r.destination_arg > 0)
      fmt::print("ok    derived from the effects: {} leaves its argument {} at its argument {} (commands say where)\n",
                 r.action, r.focal_arg, r.destination_arg);
  for (const auto& r : spec.language.salient_actions)
    if (r.focal_is_place)
      fmt::print("ok    derived from the types: {}'s argument {} is a place, named in commands (\"({} you <place>)\")\n",
                 r.action, r.focal_arg, r.action);
  try {
    for (const auto& [type, lemma] : language::dataset_type_nouns(ds)) {
      if (lemma.empty())
        fmt::print("WARN  WordNet does not know the type name '{}': its objects are understood by that word and "
                   "their qualifiers only (no synonyms, no \"a kind of ...\"); an English noun as the name, "
                   "or a corpus in the pack, would help\n",
                   type);
      else if (lemma != type)
        fmt::print("ok    derived from the types: {} is read as WordNet's \"{}\"\n", type, lemma);
    }
    for (const auto& [type, sense] : language::dataset_noun_senses(ds))
      fmt::print("ok    derived from the types: {} means \"{}\" (WordNet noun sense {}, not the first)\n", type,
                 lm::WordNetLexicon::instance().noun_gloss(type, sense), sense + 1);
  } catch (const std::exception& e) {
    // A problem that does not load is reported with the plans below.
    fmt::print("WARN  the type names' WordNet senses were not derived: {}\n", e.what());
  }
}

}  // namespace

void register_validate(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Simulate every observed plan and its completion; check the true goals; rehearse " + util::program_name() +
                      " bench on one plan");
  auto dataset = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto plans_only = std::make_shared<bool>(false);
  auto lm = std::make_shared<LmFlags>();
  add_dataset_option(cmd, *dataset, "Dataset directory (with domain.pddl, problems/, plans/)");
  cmd->add_flag("-q,--quiet", *quiet, "Print only failures, warnings and the final lines");
  cmd->add_flag("--plans-only", *plans_only,
                "Check the plans only; skip the rehearsal of " + util::program_name() + " bench (every method's set-up on the first plan "
                "that checks, with tiny search budgets)");
  add_lm_options(cmd, *lm);
  cmd->callback([=] {
    const std::string dir = dataset_dir(*dataset);
    const int schema_failures = check_pack_schema(dir, *quiet);
    auto ds = data::Dataset::load(dir);
    if (!*quiet) print_derived(ds);
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
    g_exit_code = report.failed == 0 && bench_failures == 0 && schema_failures == 0 ? kExitOk : kExitSomeFailed;
  });
}

}  // namespace clips::app
