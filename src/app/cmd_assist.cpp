// `clips assist`: one assistive run on one plan, with its metrics.
#include <fmt/core.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "eval/experiment.hpp"
#include "language/listener.hpp"

namespace clips::app {

void register_assist(CLI::App& app) {
  auto* cmd = app.add_subcommand("assist", "Infer the goal from a plan's prefix and utterance, then assist; print metrics");
  struct Opts {
    std::string dataset, plan, method = "clips", assist = "qmdp_offline";
    LmFlags lm;
    bool json = false;
    uint64_t seed = 1;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--dataset", o->dataset, "Dataset directory")->required();
  cmd->add_option("--plan", o->plan, "Plan id, e.g. 2.1.keys")->required();
  cmd->add_option("--method", o->method,
                  "clips, lang_only, action_only, literal_naive, literal_efficient (VH: literal), multimodal")
      ->check(CLI::IsMember({"clips", "lang_only", "action_only", "literal_naive", "literal_efficient", "literal",
                             "multimodal"}));
  auto mm = std::make_shared<eval::MultimodalOptions>();
  cmd->add_option("--chat-base-url", mm->base_url,
                  "multimodal: OpenAI-compatible chat endpoint (or $CLIPS_CHAT_BASE_URL, else the OpenAI API)");
  cmd->add_option("--chat-model", mm->model, "multimodal: chat model (or $CLIPS_CHAT_MODEL)");
  cmd->add_option("--assist", o->assist, "qmdp_offline (default), qmdp_online or pibar (inference methods)")
      ->check(CLI::IsMember({"qmdp_offline", "qmdp_online", "pibar"}));
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  add_assistance_options(cmd, o->lm);
  cmd->add_option("--seed", o->seed, "Seed for the literal listeners' sampling");
  cmd->add_flag("--json", o->json, "Print one JSON object");
  cmd->callback([o, mm] {
    auto ds = data::Dataset::load(o->dataset);
    if (const auto known = eval::known_methods(ds.kind());
        std::find(known.begin(), known.end(), o->method) == known.end())
      throw InputError("--method " + o->method + " does not apply to a " + data::to_string(ds.kind()) + " dataset");
    const auto& p = ds.plan(o->plan);
    auto lm = make_lm(o->lm);
    eval::ExperimentOptions eo;
    eo.seed = o->seed;
    eo.inference_threads = 0;  // one plan: use every core
    eo.speaker_rule = inference::parse_speaker_rule(o->lm.speaker_rule);
    eo.utterance_timing = inference::parse_utterance_timing(o->lm.utterance_timing);
    eo.qa_floor = assist::parse_qa_floor(o->lm.qa_floor);
    eo.multimodal = *mm;
    bool ip = o->method == "clips" || o->method == "lang_only" || o->method == "action_only";
    std::string name = o->method;
    if (ip && o->assist != "qmdp_offline") name += "/" + o->assist;
    // Relative metrics need the CLIPS reference run on the same plan.
    eo.methods = {"clips"};
    if (name != "clips") eo.methods.push_back(name);
    auto outcome = eval::evaluate_plan(ds, p, *lm, eo);
    if (!outcome.error.empty()) throw InputError(outcome.error);
    for (const auto& w : outcome.utterance_warnings) fmt::print(stderr, "warning: {}\n", w);
    const eval::MethodResult* r = outcome.find(name);
    if (!r->error.empty()) throw InputError(name + ": " + r->error);
    for (auto& n : r->notes) fmt::print(stderr, "{}: {}\n", name, n);
    if (o->json) {
      nlohmann::ordered_json j;
      j["plan"] = p.id;
      j["method"] = name;
      j["goal_reached"] = r->goal_success >= 0.5;
      j["goal_success"] = r->goal_success;
      j["plan"] = r->plan;
      j["plan_length"] = r->plan_length;
      j["plan_cost"] = r->plan_cost;
      j["human_cost"] = r->human_cost;
      j["rel_plan_length"] = r->rel_plan_length;
      j["rel_human_cost"] = r->rel_human_cost;
      j["assist_options"] = r->options;
      j["true_options"] = outcome.true_options;
      j["assist_precision"] = r->precision;
      j["assist_recall"] = r->recall;
      if (r->p_true_goal) j["p_true_goal"] = *r->p_true_goal;
      j["goals"] = outcome.goals;
      j["goal_posterior"] = r->goal_posterior;
      j["utterance_warnings"] = outcome.utterance_warnings;
      fmt::print("{}\n", j.dump());
    } else {
      fmt::print("plan {} method {}\n", p.id, name);
      for (auto& a : r->plan) fmt::print("  {}\n", a);
      fmt::print("goal reached: {} (success {:.2f}); length {:.2f}, cost {:.2f}, human cost {:.2f}\n",
                 r->goal_success >= 0.5 ? "yes" : "no", r->goal_success, r->plan_length, r->plan_cost, r->human_cost);
      std::string opts;
      for (auto& [k, v] : r->options) opts += fmt::format(" {}={:.2f}", k, v);
      std::string truth;
      for (auto& t : outcome.true_options) truth += " " + t;
      fmt::print("options:{}  (true:{})  precision {:.2f} recall {:.2f}\n", opts.empty() ? " none" : opts, truth,
                 r->precision, r->recall);
      if (r->p_true_goal) fmt::print("P(true goal) = {:.3f}\n", *r->p_true_goal);
    }
  });
}

}  // namespace clips::app
