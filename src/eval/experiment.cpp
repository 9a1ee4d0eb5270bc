#include "eval/experiment.hpp"

#include "eval/requested.hpp"

#include <algorithm>
#include <chrono>

#include "assist/assist.hpp"
#include "assist/request.hpp"
#include "assist/setup.hpp"
#include "data/validate.hpp"
#include "engine/methods.hpp"
#include "engine/options.hpp"
#include "engine/runs.hpp"
#include "domains/pack.hpp"
#include "eval/methods.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"

namespace clips::eval {

using inference::Modality;

const MethodResult* PlanOutcome::find(const std::string& m) const {
  for (auto& r : methods)
    if (r.method == m) return &r;
  return nullptr;
}

std::vector<std::string> default_methods(const domains::Pack& pack, bool all_assistance) {
  std::vector<std::string> m = engine::posterior_method_names();
  if (pack.spec().literal.enabled && !pack.language().salient_actions.empty())
    m.insert(m.end(), pack.spec().literal.methods.begin(), pack.spec().literal.methods.end());
  if (all_assistance) {
    // Each inference method with every policy but the default (already there, bare).
    const auto& policies = assist_policy_choices().entries();
    for (const std::string& base : engine::posterior_method_names())
      for (size_t k = 1; k < policies.size(); ++k) m.push_back(composite_method_name(base, policies[k].value));
  }
  return m;
}

std::vector<std::string> known_methods(const domains::Pack& pack) {
  std::vector<std::string> m = default_methods(pack, true);
  for (const std::string& b : baseline_choices().names()) m.push_back(b);
  return m;
}

bool is_method_name(const std::string& name) {
  const auto all = all_method_names();
  return std::find(all.begin(), all.end(), name) != all.end();
}

namespace {

// The inference settings an experiment asks for, the same for dataset plans
// and for ad-hoc observations.
inference::InferenceOptions inference_options(const ExperimentOptions& opts) {
  inference::InferenceOptions io;
  io.utterance.speaker_rule = opts.speaker_rule;
  io.utterance.plans = opts.speaker_plans;
  io.utterance_noise = opts.utterance_noise;
  io.utterance_exponent = opts.utterance_exponent;
  io.threads = opts.inference_threads;
  io.utterance_timing = opts.utterance_timing;
  io.assistant_turns = opts.assistant_turns;
  if (opts.refine_max_nodes > 0) io.refine.max_nodes = opts.refine_max_nodes;
  io.refine.deadline = opts.deadline;
  engine::apply_particle_options(opts.particles, io);
  return io;
}


}  // namespace

namespace {

// The hypothesis of the plan's true goal and cost profile.
int true_hypothesis(const inference::InferenceRun& inf, const data::PlanRecord& p) {
  const inference::Belief& belief = *inf.belief;
  int true_h = -1;
  for (size_t h = 0; h < belief.hypotheses().size(); ++h)
    if (belief.hypotheses()[h].goal == inf.true_goal && belief.hypotheses()[h].profile == inf.true_profile)
      true_h = static_cast<int>(h);
  if (true_h < 0) throw InputError("plan " + p.id + ": the true specification is not among the hypotheses");
  return true_h;
}

// The assistance rule and budgets of `clips bench`'s episodes.
assist::SetupOptions assistance_options(const ExperimentOptions& opts) {
  assist::SetupOptions so;
  so.rule = opts.assist_rule;
  so.qa_floor = opts.qa_floor;
  so.deadline = opts.deadline;
  so.registered_options = engine::registered_option_values(opts.particles);
  return so;
}

}  // namespace

PlanOutcome evaluate_plan(const data::Dataset& ds, const data::PlanRecord& p, lm::LanguageModel& lm,
                          const ExperimentOptions& opts) {
  auto t0 = std::chrono::steady_clock::now();
  PlanOutcome out;
  out.plan_id = p.id;
  out.split = p.split;
  out.categories = p.categories;
  out.requested = p.requested;
  if (!p.observed.utterances.empty()) out.instruction_step = p.observed.utterances.back().index;
  try {
    auto task = ds.task(p.problem_id);
    if (!p.requested.empty()) parse_requested(*task, p.requested, requested_where(ds, p));  // a bad entry fails the plan
    const domains::Pack& pack = ds.pack();
    out.true_options = data::true_options(ds, p);
    auto methods = opts.methods.empty() ? default_methods(pack, opts.all_assistance) : opts.methods;
    if (opts.methods.empty() && opts.multimodal.configured()) methods.push_back(baseline_choices().name(Baseline::Multimodal));  // issue 8

    const inference::InferenceOptions io = inference_options(opts);
    inference::InferenceRun inf = engine::run_inference(ds, p, lm, io);
    if (opts.on_inference) opts.on_inference(inf);
    out.goals = inf.goals;
    out.utterance_warnings = inf.utterance_warnings;
    out.true_goal = inf.true_goal;
    for (const auto& st : inf.steps) out.goal_posterior_steps.push_back(st[Modality::Both].goals);  // issue 8
    for (const auto& st : inf.steps) {
      out.step_seconds.push_back(st.seconds);
      out.step_work_seconds.push_back(st.work_seconds);
    }
    out.inference_threads = inf.belief->refine_threads();
    const int true_h = true_hypothesis(inf, p);
    // Particle inference: the policies the methods read (every modality's
    // weighted hypotheses, the true one for the multimodal baseline) must have
    // followed the whole observed history.
    for (Modality m : inference::kModalities) inf.belief->sync_policies(m);
    inf.belief->sync_policies({true_h});
    auto true_spec = inf.belief->hypotheses()[true_h].spec;
    const assist::AssistSetup setup = assist::setup_for_plan(pack, task, *inf.belief, p, assistance_options(opts));

    // Every method is built first, so an unknown name fails before any work.
    std::vector<std::unique_ptr<Method>> runners;
    for (const std::string& m : methods) runners.push_back(make_method(m));
    const PlanContext ctx{ds, p, lm, opts, task, inf, true_h, true_spec, setup, out.true_options};
    for (const auto& method : runners) {
      auto mt = std::chrono::steady_clock::now();
      MethodResult r;
      r.method = method->name();
      // A method that cannot run on this plan fails its own row only.
      try {
        method->run(ctx, r);
      } catch (const std::exception& e) {
        MethodResult failed;
        failed.method = r.method;
        failed.error = e.what();
        failed.failure = std::current_exception();
        r = std::move(failed);
      }
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - mt).count();
      out.methods.push_back(std::move(r));
    }
    if (const MethodResult* ref = out.find("clips"); ref && ref->error.empty()) {
      for (auto& r : out.methods) {
        r.rel_plan_length = ref->plan_length > 0 ? r.plan_length / ref->plan_length : 0;
        r.rel_human_cost = ref->human_cost > 0 ? r.human_cost / ref->human_cost : 0;
        r.has_relative = true;
      }
    }
  } catch (const std::exception& e) {
    out.error = e.what();
    out.failure = std::current_exception();
    out.methods.clear();  // a plan that failed has no method rows (results.csv, summary.json and the table agree)
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

bool is_missing_goal_atoms(const std::string& error) {
  return error.find("no goal atoms configured for action") != std::string::npos;
}

BenchCheck check_bench_setup(const data::Dataset& ds, const data::PlanRecord& p, lm::LanguageModel& lm,
                             const ExperimentOptions& opts_in) {
  BenchCheck out;
  out.plan_id = p.id;
  ExperimentOptions opts = opts_in;
  if (opts.refine_max_nodes == 0) opts.refine_max_nodes = 256;
  const domains::Pack& pack = ds.pack();
  const auto methods = opts.methods.empty() ? default_methods(pack, opts.all_assistance) : opts.methods;
  auto failed = [&](const std::string& what, const std::string& error) {
    if (is_missing_goal_atoms(error))
      out.warnings.push_back(what + ": " + error + " (language.goal_atoms); the literal listener cannot plan for it");
    else
      out.failures.push_back({what, error});
  };

  // What every method shares: inference in three modalities and the assistance set-up.
  std::shared_ptr<const pddl::Task> task;
  inference::InferenceRun inf;
  std::vector<std::string> true_options;
  int true_h = -1;
  std::optional<assist::AssistSetup> setup;
  try {
    task = ds.task(p.problem_id);
    true_options = data::true_options(ds, p);
    for (const std::string& m : methods) make_method(m);  // an unknown name, before any work
    inf = engine::run_inference(ds, p, lm, inference_options(opts));
    true_h = true_hypothesis(inf, p);
    for (Modality m : inference::kModalities) inf.belief->sync_policies(m);
    inf.belief->sync_policies({true_h});
    assist::SetupOptions so = assistance_options(opts);
    so.max_nodes = opts.refine_max_nodes;
    so.max_seconds = 5;
    so.max_steps = 2;
    setup = assist::setup_for_plan(pack, task, *inf.belief, p, so);
    // The Q_MDP episode's turn atom and no-ops (its Episode asks them first).
    assist::assistant_turn(*setup, setup->start);
    for (const std::string* agent : {&setup->principal, &setup->assistant}) setup->noop(*task, *agent);
  } catch (const std::exception& e) {
    failed("inference and assistance set-up", e.what());
    return out;
  }
  const PlanContext ctx{ds, p, lm, opts, task, inf, true_h, inf.belief->hypotheses()[true_h].spec, *setup, true_options};
  for (const std::string& m : methods) {
    MethodResult r;
    r.method = m;
    try {
      make_method(m)->run(ctx, r);
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    if (r.error.empty()) out.passed.push_back(m);
    else if (r.error.find("goal atom '") != std::string::npos) failed(m, r.error + " (language.goal_atoms)");
    else failed(m, r.error);
  }

  // Each salient action's goal, as the literal listener would compile it for
  // a command naming the action (the listener's short run plans only for the
  // most probable ones).
  const bool literal = std::any_of(methods.begin(), methods.end(),
                                   [](const std::string& m) { return m.rfind("literal", 0) == 0; });
  if (literal) {
    try {
      const auto lsetup = language::literal_listener_setup(ds.pack_ptr());
      const auto commands = language::literal_commands(*task, setup->start, lsetup);
      const auto& salient = lsetup.config.salient_actions;
      for (size_t i = 0; i < salient.size(); ++i) {
        const std::string field = "language.salient_actions[" + std::to_string(i) + "] (" + salient[i].action + ")";
        const commands::Command* found = nullptr;
        for (const auto& c : commands)
          for (const auto& a : c.actions)
            if (!found && a.name == salient[i].action && c.actions.size() == 1) found = &c;
        if (!found) {
          out.warnings.push_back(field + ": no command names it in the state after plan " + p.id +
                                 "'s observed actions, so its goal atoms are not checked here");
          continue;
        }
        try {
          language::compile_command_goal(*task, *found, lsetup.config);
        } catch (const std::exception& e) {
          failed("literal listener: the goal of " + found->display_form(),
                 std::string(e.what()) + (is_missing_goal_atoms(e.what()) ? "" : " (language.goal_atoms." + salient[i].action + ")"));
        }
      }
    } catch (const std::exception& e) {
      failed("literal listener: commands", e.what());
    }
  }

  // The assistance options: precision and recall count the assistant's actions
  // that are options; with none in the problem they are 0 for every method.
  try {
    bool any = false;
    const auto assistant = task->find_object(pack.roles().assistant);
    for (pddl::ActionId a = 0; a < task->num_actions() && !any; ++a)
      any = !task->action(a).args.empty() && assistant && task->action(a).args[0] == *assistant &&
            pack.option_of(*task, a, p.tag).has_value();
    if (!any)
      out.warnings.push_back("assistance_options: no action of the assistant '" + pack.roles().assistant +
                             "' in problem " + p.problem_id + " is an assistance option, so assistance precision and "
                             "recall are 0 for every method");
  } catch (const std::exception& e) {
    failed("assistance options", e.what());
  }
  return out;
}

LiveDecision decide_next_action(const data::Dataset& ds, const data::PlanRecord& observations,
                                std::shared_ptr<lm::LanguageModel> lm, const ExperimentOptions& opts,
                                const std::string& method, Assistance assistance, const CallLimits& limits) {
  const clips::Method m = clips::parse_method(method);
  if (m == clips::Method::Literal)
    throw InputError("--method " + method + " cannot assist from ad-hoc observations (" +
                     util::or_list(engine::posterior_method_names()) + ")");
  SessionOptions so;
  so.method = m;
  so.assistance = assistance;
  so.qa_floor = assist::to_string(opts.qa_floor);
  if (opts.assist_rule) so.assist_rule = assist::to_string(*opts.assist_rule);
  engine::Engine e = engine::engine_over_observations(ds, observations, std::move(lm), inference_options(opts), so, limits);
  LiveDecision out;
  out.goals = e.goal_labels();
  out.posterior = e.posterior();
  out.goal_posterior = out.posterior.goal_probabilities;
  out.decision = e.assist(limits);
  out.next_actor = e.active_agent();
  if (out.decision.assistant_turn) out.action = out.decision.action;
  return out;
}

}  // namespace clips::eval
