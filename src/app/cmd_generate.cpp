// `clips generate`: a dataset of random problems and sampled plans with known
// true goals (generate/generate.hpp), in the layout the other subcommands load.
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "generate/generate.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

const CLI::Validator GridSize(
    [](std::string& in) -> std::string {
      static const std::regex re(R"(^[0-9]{1,4}x[0-9]{1,4}$)");
      if (std::regex_match(in, re)) return {};
      return in + " is not a grid size WxH (e.g. 9x9)";
    },
    "WxH");

const CLI::Validator TemperatureValue(
    [](std::string& in) -> std::string {
      if (in == "prior") return {};
      char* end = nullptr;
      const double v = std::strtod(in.c_str(), &end);
      if (!in.empty() && end == in.c_str() + in.size() && std::isfinite(v) && v > 0) return {};
      return in + " is not a temperature (a number > 0, or 'prior')";
    },
    "T>0|prior");

}  // namespace

void register_generate(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "generate",
      "Write a dataset of random problems and plans sampled from the human model, with known true goals "
      "(doors-keys-gems): problems/ (PDDL and map pictures), plans/, utterances/ and generation.json (each plan's "
      "goal, tag, command and utterance); see docs/cli.md, \"Generating datasets\"");
  struct Opts {
    std::string domain = "doors-keys-gems", domain_file, size = "9x9", out, temperature = "0.5";
    int gems = 4, keys = 2, doors = 2, problems = 1, plans = 2, max_steps = 0;
    uint64_t seed = 0;
    size_t max_nodes = size_t{1} << 18;
    bool force = false, quiet = false;
    LmFlags lm;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--domain", o->domain,
                  "Domain pack that draws the problems (default doors-keys-gems, the only one that can so far)");
  cmd->add_option("--domain-file", o->domain_file,
                  "PDDL domain copied into the dataset (default: domains/<domain>/domain.pddl in the data folder)");
  cmd->add_option("--size", o->size, "Grid width x height (default 9x9; 3..40 each)")->check(GridSize);
  cmd->add_option("--gems", o->gems, "Gems, the candidate goals (default 4; at most 64, colours cycling red, yellow, blue, green)")->check(PositiveInteger);
  cmd->add_option("--keys", o->keys, "Keys (default 2)")->check(NonNegativeInteger);
  cmd->add_option("--doors", o->doors, "Locked doors, each on a chokepoint of a wall (default 2)")
      ->check(NonNegativeInteger);
  cmd->add_option("--problems", o->problems, "Problems (maps) to draw (default 1, at most 1000)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--plans", o->plans, "Plans per problem (default 2, at most 100)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 100));
  cmd->add_option("--seed", o->seed, "Random seed (default 0); the same arguments and seed give the same files")
      ->check(SeedValue);
  cmd->add_option("--temperature", o->temperature,
                  "Boltzmann temperature of the sampled actions (default 0.5), or 'prior' to draw one per plan from "
                  "the pack's temperature prior (noisy: long plans)")
      ->check(TemperatureValue);
  cmd->add_option("--max-steps", o->max_steps,
                  "Longest sampled plan (default: the pack's horizon, 100 for mDKG; at most 10000)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--max-nodes", o->max_nodes,
                  "Expansion budget per A* search of the simulated human's refinements (default 2^18); infer and "
                  "bench with the same --max-nodes to score the data with the model that drew it")
      ->check(PositiveInteger)
      ->check(NodeBudget);
  cmd->add_option("--out", o->out, "Dataset folder to write")->required();
  cmd->add_flag("--force", o->force, "Replace the dataset in a non-empty --out folder");
  cmd->add_flag("-q,--quiet", o->quiet, "Print only the final line");
  add_lm_options(cmd, o->lm);
  cmd->callback([o] {
    if (o->out.empty()) throw UsageError("--out is empty: give the folder to write the dataset to");
    generate::GenerateOptions g;
    const size_t x = o->size.find('x');
    g.map.width = std::stoi(o->size.substr(0, x));
    g.map.height = std::stoi(o->size.substr(x + 1));
    g.map.counts = {{"gem", o->gems}, {"key", o->keys}, {"door", o->doors}};
    g.problems = o->problems;
    g.plans_per_problem = o->plans;
    g.seed = o->seed;
    g.max_steps = o->max_steps;
    g.refine_nodes = o->max_nodes;
    g.temperature = o->temperature == "prior" ? std::nullopt : std::optional<double>(std::stod(o->temperature));
    g.lm = o->lm.kind;
    check_lm_server(o->lm);
    g.lm_options = lm_options(o->lm);
    if (o->domain_file.empty() && domains::builtin_pack(o->domain)->generated_kinds().empty())
      throw InputError("the " + o->domain + " pack cannot generate problems (only doors-keys-gems can so far)");
    g.domain_file = o->domain_file.empty() ? util::data_path("domains/" + o->domain + "/domain.pddl") : o->domain_file;
    if (!o->force && std::filesystem::exists(o->out) && !std::filesystem::is_empty(o->out))
      throw InputError("--out " + o->out + " is not empty (give --force to replace the dataset there)");

    const generate::GeneratedDataset ds = generate::generate_dataset(g);
    generate::write_dataset(ds, o->out, o->force);
    if (!o->quiet)
      for (const auto& p : ds.plans)
        fmt::print("{:<14} goal={:<5} T={:<3} completion={:<3} options={:<12} \"{}\"\n", p.id, p.goal,
                   p.observed_steps, p.completed_steps, fmt::format("{}", fmt::join(p.options, ",")), p.utterance);
    fmt::print(stderr, "wrote {} problems and {} plans to {}\n", g.problems, ds.plans.size(), o->out);
  });
}

}  // namespace clips::app
