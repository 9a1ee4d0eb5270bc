// `clips bench`: reproduce the paper's result tables on a dataset directory;
// `clips bench --shard K/N` runs one part of such a sweep and `clips bench
// merge` joins the parts (eval/bench_shards.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <system_error>

#include "app/choice_option.hpp"
#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "app/scaling_cli.hpp"
#include "app/particle_flags.hpp"
#include "eval/bench.hpp"
#include "eval/methods.hpp"
#include "studies/particle_eval.hpp"
#include "eval/bench_shards.hpp"
#include "report/report.hpp"
#include "util/data_dir.hpp"
#include "util/program_name.hpp"

namespace clips::app {

namespace {

namespace fs = std::filesystem;

struct ShardSpec {
  int k = 1, n = 1;
};

// "K/N" with 1 <= K <= N; nullopt and a reason otherwise.
std::optional<ShardSpec> parse_shard(const std::string& text, std::string& why) {
  const auto slash = text.find('/');
  const auto number = [](std::string_view digits, int& value) {
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return false;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && end == digits.data() + digits.size();
  };
  ShardSpec s;
  const std::string_view all(text);
  if (slash == std::string::npos || !number(all.substr(0, slash), s.k) || !number(all.substr(slash + 1), s.n)) {
    why = text + " is not K/N (e.g. 2/8: the 2nd of 8 parts)";
    return std::nullopt;
  }
  if (s.n < 1) why = text + ": N must be at least 1";
  else if (s.k < 1 || s.k > s.n) why = fmt::format("{}: K must be from 1 to N ({})", text, s.n);
  if (!why.empty()) return std::nullopt;
  return s;
}

// CLI11 prefixes the message with the flag's name: "--shard: 4/3: K must be ...".
const CLI::Validator ShardValue(
    [](std::string& in) -> std::string {
      std::string why;
      parse_shard(in, why);
      return why;
    },
    "K/N");

// Output directories are checked (and made) before any long work, not after it.
void prepare_output_dirs(const std::vector<std::pair<const char*, const std::string*>>& dirs) {
  for (auto [flag, dir] : dirs) {
    if (dir->empty()) continue;
    std::error_code ec;
    if (fs::exists(*dir, ec) && !fs::is_directory(*dir, ec))
      throw InputError(fmt::format("{} {} exists and is not a directory", flag, *dir));
    fs::create_directories(*dir, ec);
    if (ec) throw InputError(fmt::format("{}: cannot create directory {}: {}", flag, *dir, ec.message()));
  }
}

// `--out ""` (an unset variable in a script) would silently write nothing.
void reject_empty(const CLI::Option* opt, const std::string& value) {
  if (opt->count() > 0 && value.empty()) throw UsageError(opt->get_name() + " is empty: give a directory");
}

// What bench and bench merge print and write once they have a report.
void emit(const eval::BenchReport& rep, const std::string& out, const std::string& report, int jobs) {
  fmt::print("{}", eval::results_table(rep, util::data_dir() + "/paper/results.json"));
  if (!out.empty()) {
    eval::write_bench_files(rep, out);
    fmt::print(stderr, "wrote {0}/summary.json, {0}/results.csv, {0}/posteriors.csv and {0}/outcomes.json{1}\n", out,
               rep.failed_plans || rep.failed_methods ? " (failures: see the error column)" : "");
  }
  if (!report.empty()) {
    report::ReportOptions ro;
    ro.dir = report;
    ro.paper_json = util::data_dir() + "/paper/results.json";
    ro.jobs = jobs;
    fmt::print(stderr, "wrote {}\n", report::write_report(rep, ro));
  }
  // A method that failed on some plan is a failure too, though the others' rows stand.
  g_exit_code = rep.failed_plans == 0 && rep.failed_methods == 0 ? kExitOk : kExitSomeFailed;
}

// On stderr: which part of the sweep a shard ran, and plainly when it has no plan.
void note_shard(const eval::BenchReport& rep) {
  if (rep.shards.count == 1) return;
  const int k = rep.shards.present.front();
  if (rep.plans.empty())
    fmt::print(stderr,
               "bench: shard {}/{} has no plans (the sweep has {}, dealt round-robin); its files have no rows, "
               "and `{} bench merge` takes it like any other shard\n",
               k, rep.shards.count, rep.selection.size(), util::program_name());
  else
    fmt::print(stderr, "bench: shard {}/{}: {} of the sweep's {} plans\n", k, rep.shards.count, rep.plans.size(),
               rep.selection.size());
}

// The pictures of a merged report need the dataset the shards ran on.
void load_dataset_for_report(eval::BenchReport& rep, const std::string& given) {
  const std::string dir = given.empty() ? rep.dataset : dataset_dir(given);
  const std::string fingerprint = eval::dataset_fingerprint(dir);
  if (fingerprint != rep.fingerprint)
    throw InputError(fmt::format("--report needs the dataset the shards ran on (fingerprint {}), but {} has "
                                 "fingerprint {}: give its folder with --dataset",
                                 rep.fingerprint, dir, fingerprint));
  rep.loaded = std::make_shared<const data::Dataset>(data::Dataset::load(dir));
}

void register_merge(CLI::App* bench) {
  auto* cmd = bench->add_subcommand(
      "merge",
      "Merge the --out folders of `" + util::program_name() + " bench --shard K/N` runs into the files of one unsharded run: plans in "
      "dataset order, means and standard errors over all of them (no plan runs again)");
  auto out = std::make_shared<std::string>();
  auto report = std::make_shared<std::string>();
  auto dataset = std::make_shared<std::string>();
  auto parts = std::make_shared<std::vector<std::string>>();
  auto allow_partial = std::make_shared<bool>(false);
  cmd->add_option("parts", *parts, "The shards' --out folders (each holds outcomes.json)")->required();
  auto* out_opt = cmd->add_option("--out", *out, "Write the merged summary.json, results.csv, posteriors.csv and "
                                                 "outcomes.json into this directory")
                      ->required();
  auto* report_opt = cmd->add_option("--report", *report, "Also write DIR/report.html, as `" + util::program_name() + " bench --report`");
  cmd->add_option("--dataset", *dataset,
                  "With --report: the dataset folder for the pictures (default: the one the shards recorded; its "
                  "fingerprint must be theirs)");
  cmd->add_flag("--allow-partial", *allow_partial,
                "Merge even when some of the N shards are missing; summary.json's \"shards\" then lists them");
  cmd->callback([=] {
    for (const CLI::Option* opt : bench->get_options())
      if (opt->count() > 0)
        throw UsageError(opt->get_name() + " is an option of `" + util::program_name() + " bench`, not of `" + util::program_name() + " bench merge`");
    reject_empty(out_opt, *out);
    reject_empty(report_opt, *report);
    std::vector<eval::BenchPart> read;
    for (const std::string& dir : *parts) {
      std::error_code ec;
      if (fs::exists(*out, ec) && fs::exists(dir, ec) && fs::equivalent(*out, dir, ec))
        throw UsageError("--out " + *out + " is one of the parts: merging would overwrite it");
      read.push_back({dir, eval::read_bench_part(dir)});
    }
    eval::MergeOptions mo;
    mo.allow_partial = *allow_partial;
    auto rep = eval::merge_bench_parts(std::move(read), mo);
    if (!report->empty()) load_dataset_for_report(rep, *dataset);
    prepare_output_dirs({{"--out", out.get()}, {"--report", report.get()}});
    if (rep.shards.partial()) fmt::print(stderr, "bench merge: {}\n", eval::partial_note(rep));
    emit(rep, *out, *report, 0);
  });
}

void register_particles(CLI::App* bench) {
  auto* cmd = bench->add_subcommand(
      "particles",
      "Compare particle inference with exact inference on every plan: total variation between their goal "
      "posteriors (CLIPS modality; after the last step and averaged over steps) and the time and refinement "
      "ratios particle / exact, per particle count. Single-threaded, one plan at a time");
  auto o = std::make_shared<studies::ParticleEvalOptions>();
  auto lm = std::make_shared<LmFlags>();
  auto out = std::make_shared<std::string>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (doors-keys-gems or virtual-home layout)");
  cmd->add_option("--particles", o->particles,
                  "Particle counts to compare with exact inference (default 64,128,256; each at most 1000000)")
      ->delimiter(',')
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--seeds", o->seeds, "Particle seeds 1..S run per count and plan (default 3, at most 1000)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 1000));
  add_particle_options(cmd, o->tuning, {"particles", "particle_seed"});  // as for `clips infer`
  cmd->add_option("--plans", o->plans, "Only these plan ids (space- or comma-separated)")->delimiter(',');
  auto* out_opt = cmd->add_option("--out", *out, "Also write every run and the summary as JSON to this file");
  add_lm_options(cmd, *lm);
  add_speaker_model_options(cmd, *lm);
  cmd->add_flag("--no-progress", [o](int64_t) { o->progress = false; }, "No progress output on stderr");
  cmd->callback([=] {
    for (const CLI::Option* opt : bench->get_options())
      if (opt->count() > 0)
        throw UsageError(opt->get_name() + " is an option of `" + util::program_name() + " bench`, not of `" + util::program_name() + " bench particles`");
    reject_empty(out_opt, *out);
    o->dataset = dataset_dir(o->dataset);
    const auto ds = data::Dataset::load(o->dataset);
    o->language_model = make_lm(*lm, ds);
    {
      inference::InferenceOptions io;
      apply_model_flags(*lm, io);
      o->speaker_plans = io.utterance.plans;
    }
    o->speaker_rule = inference::parse_speaker_rule(lm->speaker_rule);
    o->utterance_timing = inference::parse_utterance_timing(lm->utterance_timing);
    o->assistant_turns = inference::parse_assistant_turns(lm->assistant_turns);
    const studies::ParticleEvalReport rep = studies::run_particle_eval(*o);
    fmt::print("{}", studies::format_particle_eval(rep));
    if (!out->empty()) {
      std::ofstream f(*out, std::ios::binary | std::ios::trunc);
      f << studies::to_json(rep).dump(2) << "\n";
      if (!f) throw InputError("cannot write " + *out);
    }
  });
}

}  // namespace

void register_bench(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench",
                                 "Run every method on every plan of a dataset and print the paper's Table 1 "
                                 "with the paper's numbers beside ours");
  auto o = std::make_shared<eval::BenchOptions>();
  auto out = std::make_shared<std::string>();
  auto assist = std::make_shared<std::string>(eval::assistance_set_choices().name(eval::AssistanceSet::Default));
  auto methods = std::make_shared<std::vector<std::string>>();
  auto shard = std::make_shared<std::string>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (doors-keys-gems or virtual-home layout)");
  auto* out_opt = cmd->add_option("--out", *out,
                                  "Write results.csv, posteriors.csv (goal posterior per plan, method, step and goal), "
                                  "summary.json and outcomes.json (every outcome at full precision, for `" + util::program_name() + " bench "
                                  "merge`) into this directory");
  cmd->add_option("--jobs,-j", o->jobs, "Plans evaluated in parallel (default: all cores; at most 256)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 256));
  cmd->add_option("--seed", o->experiment.seed, "Seed for the stochastic baselines, 0..2^64-1 (default 1)")
      ->check(SeedValue);
  auto lm = std::make_shared<LmFlags>();
  add_lm_options(cmd, *lm);
  add_speaker_model_options(cmd, *lm);
  add_assistance_options(cmd, *lm);
  add_choice_option(cmd, "--assist", *assist, eval::assistance_set_choices(), "Which assistance policies run (default: default)");
  cmd->add_option("--methods", *methods, "Subset of methods, e.g. clips lang_only literal_naive (or clips,lang_only)")
      ->delimiter(',');
  cmd->add_option("--plans", o->plans, "Only these plan ids (space- or comma-separated)")->delimiter(',');
  cmd->add_option("--shard", *shard,
                  "Run only part K of N (1 <= K <= N), e.g. ${SLURM_ARRAY_TASK_ID}/N in a job array. The plans "
                  "(evaluated ones or --plans, in dataset order; unloadable ones last) are dealt round-robin: the "
                  "plan at position i goes to part (i mod N)+1, so parts differ by at most one plan and each mixes "
                  "easy and hard problems. A part may have no plan. Join the parts' --out folders with "
                  "`" + util::program_name() + " bench merge`")
      ->check(ShardValue);
  // issue 8: HTML report and the multimodal baseline's chat endpoint.
  auto report = std::make_shared<std::string>();
  auto* report_opt = cmd->add_option("--report", *report,
                  "Also write DIR/report.html with per-plan GIFs and posterior plots (renders every plan: slower)");
  cmd->add_option("--chat-base-url", o->experiment.multimodal.base_url,
                  "Chat endpoint for the multimodal baseline (or $CLIPS_CHAT_BASE_URL); without one it is skipped")
      ->check(HttpUrl);
  cmd->add_option("--chat-model", o->experiment.multimodal.model, "Chat model (or $CLIPS_CHAT_MODEL)");
  cmd->add_flag("--no-progress", [o](int64_t) { o->progress = false; }, "No progress output on stderr");
  // Scaling curves (studies/scaling.hpp): generated datasets, one point per process.
  auto sc = std::make_shared<ScalingCli>();
  cmd->add_flag("--scaling", sc->run,
                "Scaling curves instead of a dataset: time per belief step and assistance decision, max RSS and "
                "P(g_true) against map side, number of goals and observed steps, on generated Doors-Keys-Gems sets; "
                "writes DIR/scaling.csv and DIR/scaling.svg (--out, default docs/scaling)");
  cmd->add_flag("--quick", sc->quick, "With --scaling: three smaller points per axis");
  cmd->add_option("--scaling-plans", sc->settings.plans, "With --scaling: plans per point (default 4, at most 10000)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--max-nodes", sc->settings.max_nodes,
                  "With --scaling: node budget of each lookahead search (default 2^18, as inference)")
      ->check(PositiveInteger)
      ->check(NodeBudget);
  cmd->add_option("--point-seconds", sc->settings.point_seconds,
                  "With --scaling: no further plan of a point starts after this many seconds (default 300)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--scaling-point", sc->point, "Internal: run one scaling point (AXIS:VALUE), print its CSV line")
      ->group("");
  auto particles = std::make_shared<ParticleFlags>();
  add_particle_options(cmd, *particles);
  register_merge(cmd);
  register_particles(cmd);
  cmd->callback([=] {
    // merge or particles has run (CLI11 runs a subcommand's callback first)
    if (cmd->got_subcommand("merge") || cmd->got_subcommand("particles")) return;
    if (sc->run || !sc->point.empty()) {
      reject_empty(out_opt, *out);
      if (!out->empty()) sc->out = *out;
      sc->settings.seed = o->experiment.seed;
      sc->lm_kind = lm->kind;
      g_exit_code = run_scaling_cli(*sc);
      return;
    }
    reject_empty(out_opt, *out);
    reject_empty(report_opt, *report);
    o->dataset = dataset_dir(o->dataset);
    o->lm = lm->kind;  // with --lm-base-url, --lm-model, --lm-timeout, --lm-max-reply-mb
    check_lm_server(*lm);
    o->lm_options = lm_options(*lm);
    apply_model_flags(*lm, o->experiment);
    o->experiment.multimodal.http.total_timeout = lm_timeout_ms(*lm);
    o->experiment.particles = *particles;  // checked by the flags' table
    o->experiment.all_assistance = eval::assistance_set_choices().parse(*assist) == eval::AssistanceSet::All;
    o->experiment.methods = *methods;
    if (!shard->empty()) {
      std::string why;
      const ShardSpec s = parse_shard(*shard, why).value();  // checked by ShardValue
      o->shard = s.k;
      o->shard_count = s.n;
    }
    bool wants_mm = std::find(methods->begin(), methods->end(), eval::baseline_choices().name(eval::Baseline::Multimodal)) != methods->end();
    if (wants_mm && !o->experiment.multimodal.configured())
      throw InputError("--methods multimodal needs a chat endpoint: --chat-base-url URL or $CLIPS_CHAT_BASE_URL");
    prepare_output_dirs({{"--out", out.get()}, {"--report", report.get()}});
    auto rep = eval::run_bench(*o);
    note_shard(rep);
    emit(rep, *out, *report, o->jobs);
  });
}

}  // namespace clips::app
