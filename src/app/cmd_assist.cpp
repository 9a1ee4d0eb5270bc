// `clips assist`: one assistive run on one plan, with its metrics.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>

#include <nlohmann/json.hpp>

#include "pddl/sexpr.hpp"
#include "app/choice_option.hpp"
#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "app/observations.hpp"
#include "engine/json.hpp"
#include "engine/methods.hpp"
#include "eval/methods.hpp"
#include "eval/experiment.hpp"
#include "language/listener.hpp"

namespace clips::app {

void register_assist(CLI::App& app) {
  auto* cmd = app.add_subcommand("assist", "Infer the goal from a plan's prefix and utterance, then assist; print metrics. With --problem: the assistant's "
      "next action after the given actions and utterance");
  struct Opts {
    std::string dataset, method = "clips", assist = eval::assist_policy_choices().entries().front().name;
    ObservationFlags obs;
    LmFlags lm;
    bool json = false;
    bool explain = false;
    uint64_t seed = 1;
    std::optional<double> time_limit;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory");
  add_observation_options(cmd, o->obs);
  // The bench's methods without a policy suffix (that is --assist), from the name tables.
  std::vector<std::string> methods = engine::posterior_method_names();
  for (const auto& n : domains::literal_method_choices().names()) methods.push_back(n);
  for (const auto& n : eval::baseline_choices().names()) methods.push_back(n);
  cmd->add_option("--method", o->method,
                  util::or_list(methods) + " (which literal methods apply is the domain pack's choice: "
                  "literal_listener.methods)")
      ->check(CLI::IsMember(methods));
  auto mm = std::make_shared<multimodal::MultimodalOptions>();
  cmd->add_option("--chat-base-url", mm->base_url,
                  "multimodal: OpenAI-compatible chat endpoint (or $CLIPS_CHAT_BASE_URL, else the OpenAI API)")
      ->check(HttpUrl);
  cmd->add_option("--chat-model", mm->model, "multimodal: chat model (or $CLIPS_CHAT_MODEL)");
  add_choice_option(cmd, "--assist", o->assist, eval::assist_policy_choices(),
                    "Assistance policy of the inference methods (default " + o->assist +
                        "; with --problem, the next action is its decision policy's)");
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  add_assistance_options(cmd, o->lm);
  cmd->add_option("--seed", o->seed, "Seed for the literal listeners' sampling, 0..2^64-1 (default 1)")->check(SeedValue);
  add_time_limit_option(cmd, o->time_limit, "the whole run (inference, then the decision or the assistance episode)");
  cmd->add_flag("--json", o->json, "Print one JSON object");
  cmd->add_flag("--explain", o->explain,
                "Also say why: with --problem, the rule that decided the next action; with --plan, each decision "
                "the request rule made: where the assistant carried out what it was asked, why; where actions tied in value, the tied actions with their values and how much of the request "
                "each carries out, the action taken and the command that broke the tie (in --json: \"ties\")");
  cmd->callback([o, mm] {
    check_observation_flags(o->obs);  // before loading anything
    const bool adhoc = !o->obs.problem.empty();
    const auto inference_methods = engine::posterior_method_names();
    const bool ip = std::find(inference_methods.begin(), inference_methods.end(), o->method) != inference_methods.end();
    if (adhoc && !ip)
      throw UsageError("with --problem, --method is " + util::or_list(inference_methods) +
                       " (the others need a dataset plan)");
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    bound_grounding(ds, "assist", o->time_limit);
    require_stimuli(ds);
    if (const auto known = eval::known_methods(ds.pack());
        std::find(known.begin(), known.end(), o->method) == known.end())
      throw InputError("--method " + o->method + " does not apply to a " + ds.pack().name() + " dataset");
    if (adhoc) {
      const data::PlanRecord obs = observations_record(ds, o->obs);
      auto lm = make_lm(o->lm, ds);
      eval::ExperimentOptions eo;
      eo.inference_threads = 0;
      apply_model_flags(o->lm, eo);
      const eval::LiveDecision d = with_time_limit("assist", o->time_limit, [&](const CallLimits& limits) {
        // One decision: the policy's decide() (online or offline is the same here).
        return eval::decide_next_action(ds, obs, lm, eo, o->method,
                                        eval::assist_policy_choices().parse(o->assist).decide, limits);
      });
      const auto& goals = d.goals;
      if (o->json) {
        nlohmann::ordered_json j;
        j["problem"] = obs.problem_id;
        j["method"] = o->method;
        j["observed_actions"] = obs.observed.actions.size();
        j["next_actor"] = d.next_actor;
        j["action"] = d.action ? nlohmann::ordered_json(*d.action) : nlohmann::ordered_json();
        j["goals"] = goals;
        j["goal_posterior"] = d.goal_posterior;
        // The engine's one JSON form of the posterior and the decision (engine/json.hpp).
        j["posterior"] = engine::to_json(d.posterior, parse_method(o->method));
        j["decision"] = engine::to_json(d.decision);
        fmt::print("{}\n", j.dump());
      } else {
        fmt::print("problem {} after {} observed action{} (method {})\n", obs.problem_id, obs.observed.actions.size(),
                   obs.observed.actions.size() == 1 ? "" : "s", o->method);
        for (size_t g = 0; g < goals.size(); ++g) fmt::print("  P({}) = {:.4f}\n", goals[g], d.goal_posterior[g]);
        if (d.action) {
          fmt::print("assistant's next action: {}\n", *d.action);
          if (o->explain && !d.decision.reason.empty()) fmt::print("why: {}\n", d.decision.reason);
        } else
          fmt::print("next to act: {} (the assistant has nothing to decide)\n", d.next_actor);
      }
      return;
    }
    const auto& p = ds.plan(o->obs.plan);
    auto lm = make_lm(o->lm, ds);
    eval::ExperimentOptions eo;
    eo.seed = o->seed;
    eo.inference_threads = 0;  // one plan: use every core
    apply_model_flags(o->lm, eo);
    eo.multimodal = *mm;
    eo.multimodal.http.total_timeout = lm_timeout_ms(o->lm);
    const auto started = std::chrono::steady_clock::now();
    if (o->time_limit)
      eo.deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(*o->time_limit));
    const std::string name =
        ip ? eval::composite_method_name(o->method, eval::assist_policy_choices().parse(o->assist)) : o->method;
    // Relative metrics need the CLIPS reference run on the same plan.
    eo.methods = {"clips"};
    if (name != "clips") eo.methods.push_back(name);
    auto outcome = eval::evaluate_plan(ds, p, *lm, eo);
    // A search cut at the deadline leaves numbers that depend on the clock.
    if (o->time_limit && std::chrono::steady_clock::now() >= eo.deadline)
      throw TimeLimitError(time_limit_message("assist", *o->time_limit));
    // Rethrown with their own type, so the exit status tells bad input from a failing LM server.
    if (outcome.failure) std::rethrow_exception(outcome.failure);
    if (!outcome.error.empty()) throw InputError(outcome.error);
    for (const auto& w : outcome.utterance_warnings) fmt::print(stderr, "warning: {}\n", pddl::printable(w));
    const eval::MethodResult* r = outcome.find(name);
    if (r->failure) std::rethrow_exception(r->failure);
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
      if (o->explain) j["ties"] = r->ties;
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
      if (o->explain) {
        fmt::print("request rule ({} decisions: requests carried out, ties broken{}):\n", r->ties.size(),
                   r->ties.empty() ? "; none met" : "");
        for (const auto& t : r->ties) fmt::print("  {}\n", t);
      }
    }
  });
}

}  // namespace clips::app
