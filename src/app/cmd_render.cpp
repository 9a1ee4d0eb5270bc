// `clips render`: pictures of a plan — one frame as PNG, or the observed
// prefix followed by CLIPS's assisted run as an animated GIF, with the goal
// posterior beside the grid.
#include <fmt/core.h>

#include "app/cli.hpp"
#include "eval/experiment.hpp"
#include "eval/scenes.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

void register_render(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Draw a plan: one state as PNG (--out) or the observed and assisted run as an animated GIF (--gif)");
  struct Opts {
    std::string dataset, plan, out, gif;
    LmFlags lm;
    int step = -1;
    int cell = 32;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--dataset", o->dataset, "Dataset directory")->required();
  cmd->add_option("--plan", o->plan, "Plan id, e.g. 2.1.keys")->required();
  cmd->add_option("--step", o->step,
                  "State to draw for --out: after N actions (0..T observed, T+1.. the CLIPS-assisted continuation); "
                  "default T, the end of the observed prefix")
      ->check(NonNegativeInteger);
  cmd->add_option("--out", o->out, "Write one frame as PNG");
  cmd->add_option("--gif", o->gif, "Write the observed prefix + CLIPS offline Q_MDP assistance as an animated GIF");
  cmd->add_option("--cell", o->cell, "Pixels per grid cell (default 32)")->check(CLI::Range(8, 128));
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  add_assistance_options(cmd, o->lm);
  cmd->callback([o] {
    if (o->out.empty() && o->gif.empty()) throw InputError("render: give --out F.png and/or --gif F.gif");
    if (o->step >= 0 && o->out.empty()) throw InputError("render: --step applies to --out (one frame)");
    auto ds = data::Dataset::load(o->dataset);
    const auto& p = ds.plan(o->plan);
    const int T = static_cast<int>(p.observed.actions.size());
    if (o->step < -1) throw InputError(fmt::format("render: --step {} is negative", o->step));
    const int step = o->step < 0 ? T : o->step;
    auto lm = make_lm(o->lm);
    eval::PlanRun run;
    bool need_assist = !o->gif.empty() || step > T;
    if (need_assist) {
      eval::ExperimentOptions eo;
      eo.methods = {"clips"};
      eo.inference_threads = 0;
      eo.speaker_rule = inference::parse_speaker_rule(o->lm.speaker_rule);
      eo.utterance_timing = inference::parse_utterance_timing(o->lm.utterance_timing);
      eo.qa_floor = assist::parse_qa_floor(o->lm.qa_floor);
      auto outcome = eval::evaluate_plan(ds, p, *lm, eo);
      if (!outcome.error.empty()) throw InputError(outcome.error);
      const eval::MethodResult* c = outcome.find("clips");
      run.goals = outcome.goals;
      run.observed_posterior = outcome.goal_posterior_steps;
      run.final_posterior = c->goal_posterior;
      run.assisted = c->plan;
      run.label = "CLIPS";
    } else {
      inference::InferenceOptions io;
      io.utterance.speaker_rule = inference::parse_speaker_rule(o->lm.speaker_rule);
      io.utterance_timing = inference::parse_utterance_timing(o->lm.utterance_timing);
      io.threads = 0;
      auto inf = inference::run_inference(ds, p, *lm, io);
      run.goals = inf.goals;
      for (auto& st : inf.steps) run.observed_posterior.push_back(st[inference::Modality::Both].goals);
    }
    auto frames = eval::plan_frames(ds, p, run);
    render::RenderOptions ro;
    ro.cell_px = o->cell;
    if (!o->out.empty()) {
      if (step >= static_cast<int>(frames.size()))
        throw InputError(fmt::format("render: --step {} is out of range for plan {}: 0..{} ({} observed, {} assisted)",
                                     step, p.id, frames.size() - 1, T, frames.assisted_steps));
      eval::write_plan_png(frames, static_cast<size_t>(step), o->out, ro);
      fmt::print("wrote {} (plan {}, step {}; {} observed steps)\n", o->out, p.id, step, T);
    }
    if (!o->gif.empty()) {
      eval::write_plan_gif(frames, o->gif, ro);
      fmt::print("wrote {} ({} frames: {} observed states, {} assisted steps)\n", o->gif, frames.size(), T + 1,
                 frames.assisted_steps);
    }
  });
}

}  // namespace clips::app
