// `clips render`: pictures of a plan — one frame as PNG, or the observed
// prefix followed by CLIPS's assisted run as an animated GIF, with the goal
// posterior beside the grid.
#include <fmt/core.h>

#include <cctype>
#include <filesystem>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "eval/experiment.hpp"
#include "scenes/scenes.hpp"
#include "engine/runs.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

// Checked before any work: the extension must match what is written, and an
// existing file is replaced only with --force.
void check_output_file(const char* flag, const std::string& path, const std::string& ext, bool force) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  std::string got = fs::path(path).extension().string();
  for (auto& c : got) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (got != ext)
    throw UsageError(fmt::format("{} {}: the file is written as {}, so its name must end in {}{}", flag, path,
                                 ext == ".png" ? "PNG" : "an animated GIF", ext,
                                 ext == ".png" ? " (use --gif F.gif for an animation)" : " (use --out F.png for one frame)"));
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(fmt::format("{} {} is a directory", flag, path));
  if (fs::exists(path, ec) && !force)
    throw InputError(fmt::format("{} {} exists; give --force to overwrite it", flag, path));
}

}  // namespace

void register_render(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Draw a plan: one state as PNG (--out) or the observed and assisted run as an animated GIF (--gif)");
  struct Opts {
    std::string dataset, plan, out, gif;
    LmFlags lm;
    int step = -1;
    int cell = 32;
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory");
  cmd->add_option("--plan", o->plan, "Plan id, e.g. 2.1.keys")->required();
  cmd->add_option("--step", o->step,
                  "State to draw for --out: after N actions (0..T observed, T+1.. the CLIPS-assisted continuation); "
                  "default T, the end of the observed prefix")
      ->check(NonNegativeInteger);
  cmd->add_option("--out", o->out, "Write one frame as PNG");
  cmd->add_option("--gif", o->gif, "Write the observed prefix + CLIPS offline Q_MDP assistance as an animated GIF");
  cmd->add_flag("--force", o->force, "Overwrite --out / --gif files that exist");
  cmd->add_option("--cell", o->cell, "Pixels per grid cell (default 32)")->check(CLI::Range(8, 128));
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  add_assistance_options(cmd, o->lm);
  cmd->callback([o] {
    if (o->out.empty() && o->gif.empty()) throw InputError("render: give --out F.png and/or --gif F.gif");
    if (o->step >= 0 && o->out.empty()) throw InputError("render: --step applies to --out (one frame)");
    check_output_file("--out", o->out, ".png", o->force);
    check_output_file("--gif", o->gif, ".gif", o->force);
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    const auto& p = ds.plan(o->plan);
    const int T = static_cast<int>(p.observed.actions.size());
    if (o->step < -1) throw InputError(fmt::format("render: --step {} is negative", o->step));
    const int step = o->step < 0 ? T : o->step;
    auto lm = make_lm(o->lm, ds);
    scenes::PlanRun run;
    bool need_assist = !o->gif.empty() || step > T;
    if (need_assist) {
      eval::ExperimentOptions eo;
      eo.methods = {"clips"};
      eo.inference_threads = 0;
      apply_model_flags(o->lm, eo);
      auto outcome = eval::evaluate_plan(ds, p, *lm, eo);
      if (outcome.failure) std::rethrow_exception(outcome.failure);
      if (!outcome.error.empty()) throw InputError(outcome.error);
      const eval::MethodResult* c = outcome.find("clips");
      if (c->failure) std::rethrow_exception(c->failure);
      run.goals = outcome.goals;
      run.observed_posterior = outcome.goal_posterior_steps;
      run.final_posterior = c->goal_posterior;
      run.assisted = c->plan;
      run.label = "CLIPS";
    } else {
      inference::InferenceOptions io;
      apply_model_flags(o->lm, io);
      io.threads = 0;
      auto inf = engine::run_observations(ds, p, *lm, io, /*known_truth=*/true);
      run.goals = inf.goals;
      for (auto& st : inf.steps) run.observed_posterior.push_back(st[inference::Modality::Both].goals);
    }
    auto frames = scenes::plan_frames(ds, p, run);
    render::RenderOptions ro;
    ro.cell_px = o->cell;
    if (!o->out.empty()) {
      if (step >= static_cast<int>(frames.size()))
        throw InputError(fmt::format("render: --step {} is out of range for plan {}: 0..{} ({} observed, {} assisted)",
                                     step, p.id, frames.size() - 1, T, frames.assisted_steps));
      scenes::write_plan_png(frames, static_cast<size_t>(step), o->out, ro);
      fmt::print(stderr, "wrote {} (plan {}, step {}; {} observed steps)\n", o->out, p.id, step, T);
    }
    if (!o->gif.empty()) {
      scenes::write_plan_gif(frames, o->gif, ro);
      fmt::print(stderr, "wrote {} ({} frames: {} observed states, {} assisted steps)\n", o->gif, frames.size(), T + 1,
                 frames.assisted_steps);
    }
  });
}

}  // namespace clips::app
