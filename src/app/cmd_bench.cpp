// `clips bench`: reproduce the paper's result tables on a dataset directory.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "eval/bench.hpp"
#include "eval/report.hpp"
#include "util/data_dir.hpp"

namespace clips::app {

void register_bench(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench",
                                 "Run every method on every plan of a dataset and print the paper's Table 1 "
                                 "with the paper's numbers beside ours");
  auto o = std::make_shared<eval::BenchOptions>();
  auto out = std::make_shared<std::string>();
  auto assist = std::make_shared<std::string>("default");
  auto methods = std::make_shared<std::vector<std::string>>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (doors-keys-gems or virtual-home layout)");
  auto* out_opt = cmd->add_option("--out", *out,
                                  "Write results.csv, posteriors.csv (goal posterior per plan, method, step and goal) "
                                  "and summary.json into this directory");
  cmd->add_option("--jobs,-j", o->jobs, "Plans evaluated in parallel (default: all cores)")->check(PositiveInteger);
  cmd->add_option("--seed", o->experiment.seed, "Seed for the stochastic baselines, 0..2^64-1 (default 1)")
      ->check(SeedValue);
  auto lm = std::make_shared<LmFlags>();
  add_lm_options(cmd, *lm);
  add_speaker_model_options(cmd, *lm);
  add_assistance_options(cmd, *lm);
  cmd->add_option("--assist", *assist, "default (offline Q_MDP) or all (adds online Q_MDP and pi-bar_MDP)")
      ->check(CLI::IsMember({"default", "all"}));
  cmd->add_option("--methods", *methods, "Subset of methods, e.g. clips lang_only literal_naive (or clips,lang_only)")
      ->delimiter(',');
  cmd->add_option("--plans", o->plans, "Only these plan ids (space- or comma-separated)")->delimiter(',');
  // issue 8: HTML report and the multimodal baseline's chat endpoint.
  auto report = std::make_shared<std::string>();
  auto* report_opt = cmd->add_option("--report", *report,
                  "Also write DIR/report.html with per-plan GIFs and posterior plots (renders every plan: slower)");
  cmd->add_option("--chat-base-url", o->experiment.multimodal.base_url,
                  "Chat endpoint for the multimodal baseline (or $CLIPS_CHAT_BASE_URL); without one it is skipped");
  cmd->add_option("--chat-model", o->experiment.multimodal.model, "Chat model (or $CLIPS_CHAT_MODEL)");
  cmd->add_flag("--no-progress", [o](int64_t) { o->progress = false; }, "No progress output on stderr");
  cmd->callback([=] {
    // `--out ""` (an unset variable in a script) would silently write nothing.
    if (out_opt->count() > 0 && out->empty()) throw UsageError("--out is empty: give a directory");
    if (report_opt->count() > 0 && report->empty()) throw UsageError("--report is empty: give a directory");
    o->dataset = dataset_dir(o->dataset);
    o->lm = lm->kind;  // with --lm-base-url, --lm-model, --lm-timeout, --lm-max-reply-mb
    o->lm_options = lm_options(*lm);
    o->experiment.speaker_rule = inference::parse_speaker_rule(lm->speaker_rule);
    o->experiment.utterance_timing = inference::parse_utterance_timing(lm->utterance_timing);
    o->experiment.qa_floor = assist::parse_qa_floor(lm->qa_floor);
    o->experiment.all_assistance = *assist == "all";
    o->experiment.methods = *methods;
    bool wants_mm = std::find(methods->begin(), methods->end(), "multimodal") != methods->end();
    if (wants_mm && !o->experiment.multimodal.configured())
      throw InputError("--methods multimodal needs a chat endpoint: --chat-base-url URL or $CLIPS_CHAT_BASE_URL");
    // Output directories are checked before the (long) run, not after it.
    for (auto [flag, dir] : {std::pair{"--out", out.get()}, std::pair{"--report", report.get()}}) {
      if (dir->empty()) continue;
      std::error_code ec;
      if (std::filesystem::exists(*dir, ec) && !std::filesystem::is_directory(*dir, ec))
        throw InputError(fmt::format("{} {} exists and is not a directory", flag, *dir));
      std::filesystem::create_directories(*dir, ec);
      if (ec) throw InputError(fmt::format("{}: cannot create directory {}: {}", flag, *dir, ec.message()));
    }
    auto rep = eval::run_bench(*o);
    fmt::print("{}", eval::results_table(rep, util::data_dir() + "/paper/results.json"));
    if (!out->empty()) {
      std::filesystem::create_directories(*out);
      auto write = [&](const std::string& name, const std::string& text) {
        std::string path = *out + "/" + name;
        std::ofstream f(path);
        if (!(f << text)) throw InputError("cannot write " + path);
      };
      write("summary.json", eval::summary_json(rep));
      write("results.csv", eval::results_csv(rep));
      write("posteriors.csv", eval::posteriors_csv(rep));
      fmt::print(stderr, "wrote {0}/summary.json, {0}/results.csv and {0}/posteriors.csv{1}\n", *out,
                 rep.failed_plans ? " (failed plans: see the error column)" : "");
    }
    if (!report->empty()) {
      eval::ReportOptions ro;
      ro.dir = *report;
      ro.paper_json = util::data_dir() + "/paper/results.json";
      ro.jobs = o->jobs;
      fmt::print(stderr, "wrote {}\n", eval::write_report(rep, ro));
    }
    g_exit_code = rep.failed_plans == 0 ? kExitOk : kExitSomeFailed;
  });
}

}  // namespace clips::app
