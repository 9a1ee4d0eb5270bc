// `clips infer`: goal inference over one dataset plan, or over actions and an utterance (docs/cli.md).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "pddl/sexpr.hpp"
#include "app/cli.hpp"
#include "app/observations.hpp"
#include "data/dataset.hpp"
#include "app/particle_flags.hpp"
#include "engine/json.hpp"
#include "engine/methods.hpp"
#include "engine/runs.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

std::string hypothesis_label(const inference::InferenceRun& run, size_t h) {
  const auto& hy = run.belief->hypotheses().at(h);
  return run.goals.at(hy.goal) + "/" + run.profiles.at(hy.profile);
}

// Commands of one hypothesis, most probable first, at most `top`.
std::vector<const inference::CommandScore*> top_commands(const inference::HypothesisUtterance& hu, int top) {
  std::vector<const inference::CommandScore*> cs;
  for (const auto& c : hu.commands) cs.push_back(&c);
  std::stable_sort(cs.begin(), cs.end(), [](auto* a, auto* b) { return a->posterior > b->posterior; });
  if (cs.size() > static_cast<size_t>(top)) cs.resize(static_cast<size_t>(top));
  return cs;
}

std::vector<std::string> rollout_of(const inference::InferenceRun& run, size_t h) {
  const inference::Belief& b = *run.belief;
  std::vector<std::string> out;
  for (pddl::ActionId a : b.utterance_model().rollout(b.policies().at(h), b.state()))
    out.push_back(b.task().action_name(a));
  return out;
}

nlohmann::json explain_json(const inference::InferenceRun& run, const inference::StepRecord& st, int top) {
  nlohmann::json us = nlohmann::json::array();
  for (const auto& u : st.utterances) {
    nlohmann::json hs = nlohmann::json::array();
    for (size_t h = 0; h < u.hypotheses.size(); ++h) {
      nlohmann::json cs = nlohmann::json::array();
      for (const auto* c : top_commands(u.hypotheses[h], top))
        cs.push_back({{"command", c->command}, {"log_lm", c->log_lm}, {"prior", c->prior}, {"posterior", c->posterior}});
      hs.push_back({{"hypothesis", hypothesis_label(run, h)},
                    {"log_likelihood", u.hypotheses[h].log_likelihood},
                    {"commands", std::move(cs)},
                    {"num_commands", u.hypotheses[h].commands.size()}});
    }
    us.push_back({{"text", u.text}, {"hypotheses", std::move(hs)}});
  }
  return us;
}

nlohmann::json rollouts_json(const inference::InferenceRun& run) {
  nlohmann::json out = nlohmann::json::object();
  for (size_t h = 0; h < run.belief->hypotheses().size(); ++h)
    if (run.belief->current(static_cast<int>(h))) out[hypothesis_label(run, h)] = rollout_of(run, h);
  return out;
}

void print_explanation(const inference::InferenceRun& run, int top) {
  for (const auto& st : run.steps)
    for (const auto& u : st.utterances) {
      fmt::print("\nutterance \"{}\" (step {}): log-likelihood per hypothesis, then its most probable commands (posterior, prior, LM score)\n",
                 pddl::printable(u.text), st.t);
      for (size_t h = 0; h < u.hypotheses.size(); ++h) {
        const auto& hu = u.hypotheses[h];
        if (std::isnan(hu.log_likelihood)) continue;  // particle inference: no particle held h
        // An alone twin speaks as its base: say so instead of repeating its commands.
        const auto& hy = run.belief->hypotheses().at(h);
        if (const int base = run.belief->profiles().at(static_cast<size_t>(hy.profile)).twin_of; base >= 0) {
          fmt::print("  {:<14} {:>9.3f}  (speaks as {}/{})\n", hypothesis_label(run, h), hu.log_likelihood,
                     run.goals.at(static_cast<size_t>(hy.goal)), run.profiles.at(static_cast<size_t>(base)));
          continue;
        }
        fmt::print("  {:<14} {:>9.3f}  ({} command{})\n", hypothesis_label(run, h), hu.log_likelihood,
                   hu.commands.size(), hu.commands.size() == 1 ? "" : "s");
        if (hu.commands.empty()) fmt::print("      (no command: scored with the empty prompt)\n");
        for (const auto* c : top_commands(hu, top))
          fmt::print("      {:.3f}  (prior {:.3f}, log P(u|c) {:.2f})  {}\n", c->posterior, c->prior, c->log_lm, c->command);
      }
    }
  fmt::print("\nrolled-out joint plans after the last step:\n");
  for (size_t h = 0; h < run.belief->hypotheses().size(); ++h) {
    // Particle inference: hypotheses no particle holds have not followed the history.
    if (!run.belief->current(static_cast<int>(h))) continue;
    auto plan = rollout_of(run, h);
    std::string text;
    for (const auto& a : plan) text += (text.empty() ? "" : " ") + a;
    fmt::print("  {:<14} {}\n", hypothesis_label(run, h), text.empty() ? "(none)" : text);
  }
}

// Searches cut off by the budget leave partial values behind, so the numbers
// above would change with --max-nodes: say so rather than stay silent.
void print_budget_note(const inference::InferenceRun& run, size_t max_nodes) {
  if (run.searches_stopped_by_budget == 0) return;
  fmt::print(stderr,
             "note: {} lookahead search{} stopped at the budget of {} expansions; the posterior depends on "
             "--max-nodes\n",
             run.searches_stopped_by_budget, run.searches_stopped_by_budget == 1 ? "" : "es", max_nodes);
}

}  // namespace

void register_infer(CLI::App& app) {
  auto* cmd = app.add_subcommand("infer", "Infer the human's goal from a plan's actions and instruction (CLIPS), or from actions and an utterance given "
      "with --problem");
  struct Opts {
    std::string dataset, modalities = "both";
    ObservationFlags obs;
    LmFlags lm;
    bool json = false, explain = false;
    int top = 3;
    size_t max_nodes = size_t{1} << 18;
    std::string heuristic;
    ParticleFlags particles;
    std::optional<double> time_limit;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (with domain.pddl)");
  add_observation_options(cmd, o->obs);
  // The methods with a posterior of their own, with their older spellings (the one method table).
  std::vector<std::string> with_aliases;
  for (const auto& c : engine::method_choices().entries()) {
    if (c.value == Method::Literal) continue;
    std::string also;
    for (const auto& a : c.aliases) also += (also.empty() ? "" : ", ") + a;
    with_aliases.push_back(c.name + (also.empty() ? "" : " (also " + also + ")"));
  }
  cmd->add_option("--modalities", o->modalities,
                  "Which evidence the reported posterior uses, by method name (default clips): " +
                      util::or_list(with_aliases))
      ->check(CLI::Validator(
          [](std::string& v) {
            try {
              if (parse_method(v) == Method::Literal) return std::string("literal has no posterior of its own");
              return std::string();
            } catch (const InputError& e) {
              return std::string(e.what());
            }
          },
          "METHOD"));
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  cmd->add_option("--max-nodes", o->max_nodes, "Expansion budget per A* search in each refinement (default 2^18)")
      ->check(PositiveInteger)
      ->check(NodeBudget);
  cmd->add_option("--heuristic", o->heuristic,
                  "Heuristic of the refinements (default: the domain pack's inference heuristic; an unknown name "
                  "lists the pack's heuristics)");
  add_particle_options(cmd, o->particles);
  add_time_limit_option(cmd, o->time_limit, "the whole inference");
  cmd->add_flag("--explain", o->explain,
                "Also show, per utterance and hypothesis (goal x cost profile), its likelihood and most probable "
                "commands, and each hypothesis' rolled-out joint plan at the end");
  cmd->add_option("--top", o->top, "With --explain: commands shown per hypothesis (default 3)")
      ->check(PositiveInteger);
  cmd->add_flag("--json", o->json,
                "Print {goals, true_goal, steps: [{t, action, posterior}]} as one JSON object, each posterior in "
                "the engine's form ({goals: [{goal, p}], cost_profiles, hypotheses, log_marginal_likelihood}; "
                "docs/api.md); true_goal is null for --problem observations");
  cmd->callback([o] {
    check_observation_flags(o->obs);  // before loading anything
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    bound_grounding(ds, "infer", o->time_limit);
    require_stimuli(ds);
    const bool adhoc = !o->obs.problem.empty();
    const data::PlanRecord plan = adhoc ? observations_record(ds, o->obs) : ds.plan(o->obs.plan);
    const Method method = parse_method(o->modalities);
    const inference::Modality modality = engine::modality_of(method);
    auto lm = make_lm(o->lm, ds);
    inference::InferenceOptions opts;
    opts.refine.max_nodes = o->max_nodes;
    opts.heuristic = o->heuristic;
    opts.threads = 0;  // one plan: use every core
    apply_model_flags(o->lm, opts);
    apply_particle_flags(o->particles, opts);
    const inference::InferenceRun run =
        with_time_limit("infer", o->time_limit, [&](const CallLimits& limits) {
          return engine::run_observations(ds, plan, *lm, opts, /*known_truth=*/!adhoc, limits);
        });
    // Utterances the model could not read (weighted down or ignored): the user must know.
    for (const auto& w : run.utterance_warnings) fmt::print(stderr, "warning: {}\n", pddl::printable(w));
    // Particle inference: the rollouts shown are of the modality's weighted hypotheses, brought up to date.
    if (o->explain) run.belief->sync_policies(modality);
    const std::string true_goal = run.true_goal >= 0 ? run.goals[run.true_goal] : "";
    if (o->json) {
      nlohmann::json j;
      j["plan"] = adhoc ? nlohmann::json() : nlohmann::json(run.plan_id);
      j["method"] = method_name(method);
      j["modality"] = inference::to_string(modality);
      j["goals"] = run.goals;
      j["true_goal"] = adhoc ? nlohmann::json() : nlohmann::json(true_goal);
      if (adhoc) j["problem"] = plan.problem_id;
      j["steps"] = nlohmann::json::array();
      for (const auto& st : run.steps) {
        // seconds: this step's wall time (refinements, scoring), to find the slow ones. The posterior is
        // the engine's JSON form (engine/json.hpp), as the server and Python write it.
        nlohmann::json step = {{"t", st.t},
                               {"action", st.action},
                               {"seconds", st.seconds},
                               {"posterior", engine::to_json(engine::posterior_of(run, st, method), method)}};
        if (o->explain && !st.utterances.empty()) step["utterances"] = explain_json(run, st, o->top);
        j["steps"].push_back(std::move(step));
      }
      if (o->explain) j["rollouts"] = rollouts_json(run);
      j["seconds"] = run.seconds;
      j["searches_stopped_by_budget"] = run.searches_stopped_by_budget;
      j["particles"] = o->particles.particles;
      j["utterance_warnings"] = run.utterance_warnings;
      fmt::print("{}\n", j.dump());
      print_budget_note(run, o->max_nodes);
      return;
    }
    if (adhoc)
      fmt::print("{}: goal posterior ({})\n", run.plan_id, inference::to_string(modality));
    else
      fmt::print("plan {}: goal posterior ({}), true goal {}\n", run.plan_id, inference::to_string(modality), true_goal);
    fmt::print("{:>4}  {:<30}", "t", "action");
    std::vector<size_t> width;
    for (const auto& g : run.goals) width.push_back(std::max<size_t>(9, g.size()));
    for (size_t g = 0; g < run.goals.size(); ++g) fmt::print(" {:>{}}", run.goals[g], width[g]);
    fmt::print("\n");
    for (const auto& st : run.steps) {
      fmt::print("{:>4}  {:<30}", st.t, st.t == 0 ? "(start)" : st.action);
      for (size_t g = 0; g < width.size(); ++g) fmt::print(" {:>{}.4f}", st[modality].goals[g], width[g]);
      for (const auto& u : st.utterances) fmt::print("   <- \"{}\"", pddl::printable(u.text));
      fmt::print("\n");
    }
    const auto& fin = run.steps.back()[modality];
    fmt::print("; cost profiles:");
    for (size_t c = 0; c < run.profiles.size(); ++c) fmt::print(" {} {:.4f}", run.profiles[c], fin.profiles[c]);
    fmt::print("; log marginal likelihood {:.4f}{}; {:.3f} s ({})\n", fin.log_marginal,
               o->particles.particles > 0 ? fmt::format(" (estimate, {} particles)", o->particles.particles) : "",
               run.seconds, lm->name());
    if (o->explain) print_explanation(run, o->top);
    print_budget_note(run, o->max_nodes);
  });
}

}  // namespace clips::app
