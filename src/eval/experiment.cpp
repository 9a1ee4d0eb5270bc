#include "eval/experiment.hpp"

#include <chrono>
#include <functional>

#include "assist/assist.hpp"
#include "assist/literal.hpp"
#include "data/validate.hpp"
#include "domains/dkg_goals.hpp"
#include "domains/registry.hpp"
#include "eval/metrics.hpp"
#include "inference/belief.hpp"
#include "inference/vh_value.hpp"
#include "language/commands/utterance_merge.hpp"
#include "language/listener.hpp"

namespace clips::eval {

using inference::Modality;

const MethodResult* PlanOutcome::find(const std::string& m) const {
  for (auto& r : methods)
    if (r.method == m) return &r;
  return nullptr;
}

std::vector<std::string> default_methods(data::DomainKind kind, bool all_assistance) {
  std::vector<std::string> m = {"clips", "lang_only", "action_only"};
  if (kind == data::DomainKind::VirtualHome) m.push_back("literal");
  else m.insert(m.end(), {"literal_efficient", "literal_naive"});
  if (all_assistance)
    for (const char* base : {"clips", "lang_only", "action_only"})
      for (const char* a : {"qmdp_online", "pibar"}) m.push_back(std::string(base) + "/" + a);
  return m;
}

std::vector<std::string> known_methods(data::DomainKind kind) {
  std::vector<std::string> m = default_methods(kind, true);
  m.push_back("multimodal");
  return m;
}

namespace {

struct DomainFacts {
  std::string principal, assistant;
  int horizon;
  double noop_cost;
};

DomainFacts facts_of(data::DomainKind kind) {
  if (kind == data::DomainKind::VirtualHome) return {"actor", "helper", 50, 1.0};
  return {"human", "robot", 100, 0.6};
}

// Which object an action commits the assistant to, for this plan's option type.
std::function<std::optional<std::string>(pddl::ActionId)> option_rule(const pddl::Task& task, data::DomainKind kind,
                                                                      const std::string& tag, const std::string& assistant) {
  return [&task, kind, tag, assistant](pddl::ActionId a) -> std::optional<std::string> {
    const auto& ga = task.action(a);
    if (ga.args.empty() || task.object_name(ga.args[0]) != assistant) return std::nullopt;
    const std::string& name = task.domain().actions[ga.schema].name;
    if (kind == data::DomainKind::VirtualHome) {
      if (name == "grab") return task.object_name(ga.args[1]);
      return std::nullopt;
    }
    if (tag == "keys" && (name == "pickup" || name == "handover")) {
      pddl::ObjectId item = ga.args.back();
      if (task.object_is_a(item, "key")) return task.object_name(item);
    }
    if (tag == "doors" && name == "unlock") return task.object_name(ga.args[2]);
    return std::nullopt;
  };
}

// An OnlineBelief over a copy of the inference belief, read in one modality.
class OnlineAdapter : public assist::OnlineBelief {
 public:
  OnlineAdapter(const inference::Belief& b, Modality m) : belief_(b), modality_(m) { rebuild(); }
  void observe(const pddl::State& pre, pddl::ActionId a) override {
    // Paper semantics for language-only (spec 13.10): no action evidence online.
    if (modality_ == Modality::UtteranceOnly) return;
    belief_.observe(a, pre);
    rebuild();
  }
  std::vector<assist::Hypothesis>& hypotheses() override { return hyps_; }

 private:
  void rebuild() {
    auto post = belief_.posterior(modality_);
    hyps_.clear();
    for (size_t h = 0; h < post.hypotheses.size(); ++h)
      hyps_.push_back({post.hypotheses[h], std::shared_ptr<search::Policy>(&belief_.policies()[h], [](auto*) {})});
  }
  inference::Belief belief_;
  Modality modality_;
  std::vector<assist::Hypothesis> hyps_;
};

std::vector<pddl::ActionId> resolve_all(const pddl::Task& task, const pddl::State& start, const pddl::PlanFile& pf) {
  return pddl::simulate(task, start, pf).actions;
}

}  // namespace

PlanOutcome evaluate_plan(const data::Dataset& ds, const data::PlanRecord& p, lm::LanguageModel& lm,
                          const ExperimentOptions& opts) {
  auto t0 = std::chrono::steady_clock::now();
  PlanOutcome out;
  out.plan_id = p.id;
  try {
    auto task = ds.task(p.problem_id);
    DomainFacts df = facts_of(ds.kind());
    out.true_options = data::true_options(ds, p);
    auto methods = opts.methods.empty() ? default_methods(ds.kind(), opts.all_assistance) : opts.methods;
    if (opts.methods.empty() && opts.multimodal.configured()) methods.push_back("multimodal");  // issue 8

    inference::InferenceOptions io;
    io.utterance.speaker_rule = opts.speaker_rule;
    io.threads = opts.inference_threads;
    io.utterance_timing = opts.utterance_timing;
    inference::InferenceRun inf = inference::run_inference(ds, p, lm, io);
    out.goals = inf.goals;
    out.utterance_warnings = inf.utterance_warnings;
    out.true_goal = inf.true_goal;
    for (const auto& st : inf.steps) out.goal_posterior_steps.push_back(st[Modality::Both].goals);  // issue 8
    const inference::Belief& belief = *inf.belief;
    int true_h = -1;
    for (size_t h = 0; h < belief.hypotheses().size(); ++h)
      if (belief.hypotheses()[h].goal == inf.true_goal && belief.hypotheses()[h].profile == inf.true_profile)
        true_h = static_cast<int>(h);
    if (true_h < 0) throw InputError("plan " + p.id + ": the true specification is not among the hypotheses");
    auto true_spec = belief.hypotheses()[true_h].spec;

    assist::AssistSetup setup;
    setup.task = task;
    setup.start = belief.state();
    setup.observed_steps = static_cast<int>(p.observed.actions.size());
    setup.horizon = df.horizon;
    setup.principal = df.principal;
    setup.assistant = df.assistant;
    setup.noop_cost = df.noop_cost;
    setup.completed = resolve_all(*task, setup.start, p.completed);
    setup.option_of = option_rule(*task, ds.kind(), p.tag, df.assistant);
    setup.refine = belief.searches();
    setup.qa_floor = opts.qa_floor;
    setup.follow_plan_by_index = ds.kind() == data::DomainKind::VirtualHome;  // VirtualHome reads V = -h_g and never searches

    auto modality_of = [](const std::string& base) {
      return base == "clips" ? Modality::Both : base == "lang_only" ? Modality::UtteranceOnly : Modality::ActionOnly;
    };
    auto score = [&](MethodResult& r, const assist::AssistResult& a) {
      r.options = a.options;
      r.precision = assist_precision(a.options, out.true_options);
      r.recall = assist_recall(a.options, out.true_options);
      r.plan_length = a.plan_length;
      r.human_cost = a.human_cost;
      r.plan_cost = a.plan_cost;
      r.goal_success = a.success;
      r.decision_seconds = a.decision_seconds;
      for (auto act : a.plan) r.plan.push_back(task->action_name(act));
    };

    for (const std::string& m : methods) {
      auto mt = std::chrono::steady_clock::now();
      MethodResult r;
      r.method = m;
      std::string base = m.substr(0, m.find('/'));
      std::string how = m.find('/') == std::string::npos ? "qmdp_offline" : m.substr(m.find('/') + 1);
      if (base == "clips" || base == "lang_only" || base == "action_only") {
        Modality mod = modality_of(base);
        const auto& post = inf.final_posterior(mod);
        r.p_true_goal = post.goals.at(inf.true_goal);
        r.goal_posterior = post.goals;
        for (const auto& st : inf.steps) r.posterior_steps.push_back(st[mod].goals);
        std::vector<assist::Hypothesis> hyps;
        for (size_t h = 0; h < post.hypotheses.size(); ++h)
          hyps.push_back({post.hypotheses[h], std::make_shared<search::Policy>(belief.policies()[h])});
        if (how == "qmdp_offline") {
          score(r, assist::qmdp_offline(setup, hyps, true_h));
        } else if (how == "pibar") {
          score(r, assist::pibar_mdp(setup, hyps, true_h));
        } else if (how == "qmdp_online") {
          OnlineAdapter online(belief, mod);
          std::shared_ptr<heuristics::Heuristic> h = inference::make_inference_heuristic(
              inference::inference_heuristic_name(ds.kind()), *task, ds.kind());
          if (!setup.refine) h->prepare(*true_spec, setup.start);
          score(r, assist::qmdp_online(setup, online, true_spec, h));
        } else {
          throw InputError("unknown assistance method '" + how + "' (known: qmdp_offline, qmdp_online, pibar)");
        }
      } else if (base == "literal_efficient" || base == "literal_naive" || base == "literal") {
        const data::DomainKind kind_of_ds = ds.kind();
        std::string domain = language::language_domain_of(*task);
        auto lsetup = language::literal_listener_setup(domain);
        std::string utt = p.literal_utterance ? *p.literal_utterance
                          : p.observed.utterances.empty() ? std::string() : p.observed.utterances.back().text;
        if (utt.empty()) throw InputError("plan " + p.id + " has no utterance for the literal listener");
        auto ranked = language::literal_listener(*task, setup.start, utt, lsetup, lm);
        if (kind_of_ds == data::DomainKind::VirtualHome && p.observed.utterances.size() > 1) {
          // VH spec 7.3: every utterance is heard in s_T; rankings are merged
          // (most probable prefix of the first, then each later one).
          auto to_cmd = [](const language::ListenerResult& lr) {
            std::vector<commands::RankedCommand> v;
            for (auto& c : lr.commands) v.push_back({c.command, c.prob, c.log_likelihood});
            return v;
          };
          auto kept = commands::probable_prefix(
              to_cmd(language::literal_listener(*task, setup.start, p.observed.utterances[0].text, lsetup, lm)));
          for (size_t u = 1; u < p.observed.utterances.size(); ++u)
            kept = commands::combine_utterance_rankings(
                kept, to_cmd(language::literal_listener(*task, setup.start, p.observed.utterances[u].text, lsetup, lm)));
          ranked.commands.clear();
          for (auto& k : kept) ranked.commands.push_back({k.command, k.score, k.probability});
        }
        assist::LiteralSetup ls;
        ls.world = setup;
        ls.truth = true_spec;
        ls.config = lsetup.config;
        data::DomainKind kind = ds.kind();
        ls.make_heuristic = [task, kind]() -> std::shared_ptr<heuristics::Heuristic> {
          if (kind == data::DomainKind::VirtualHome) return std::make_shared<inference::VhPlanningHeuristic>(*task);
          return domains::make_heuristic(domains::model_heuristic(kind), *task, kind);
        };
        if (kind == data::DomainKind::DoorsKeysGems) ls.goal_unsatisfiable = domains::dkg_goal_unsatisfiable;
        std::string tag = p.tag;
        ls.is_option = [task, kind, tag](const std::string& o) {
          auto id = task->find_object(o);
          if (!id) return false;
          if (kind == data::DomainKind::VirtualHome) return task->object_is_a(*id, "item");
          return task->object_is_a(*id, tag == "doors" ? "door" : "key");
        };
        for (const char* type : {"key", "door", "gem", "item", "fixture"})
          for (auto o : task->objects_of_type(type)) ls.objects_by_type[type].push_back(task->object_name(o));
        const char* qual = kind == data::DomainKind::VirtualHome ? "itemtype" : "iscolor";
        auto qpred = task->domain().find_predicate(qual);
        if (qpred) {
          const auto& types = task->domain().predicates[*qpred].arg_types;
          for (pddl::ObjectId a = 0; a < task->num_objects(); ++a) {
            if (!task->domain().is_subtype(task->problem().objects[a].type, types[0])) continue;
            for (pddl::ObjectId b = 0; b < task->num_objects(); ++b)
              if (task->domain().is_subtype(task->problem().objects[b].type, types[1]) && task->atom(*qpred, {a, b}).value)
                ls.facts.push_back(commands::Term{qual, {task->object_name(a), task->object_name(b)}});
          }
        }
        uint64_t seed = opts.seed ^ std::hash<std::string>{}(p.id + "/" + m);
        auto lr = assist::literal_assist(ls, ranked, base == "literal_naive", seed);
        score(r, lr.result);
      } else if (base == "multimodal") {
        // issue 8: multimodal-LLM baseline; its failures stay with this method.
        try {
          auto mm = run_multimodal(ds, p, setup, out.goals, belief.policies()[true_h], opts.multimodal);
          r.goal_posterior = mm.answer.goal_posterior;
          r.p_true_goal = r.goal_posterior.at(inf.true_goal);
          r.notes = mm.notes;
          score(r, mm.result);
        } catch (const std::exception& e) {
          r.error = e.what();
          r.failure = std::current_exception();
        }
      } else {
        throw InputError("unknown method '" + m + "'");
      }
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - mt).count();
      out.methods.push_back(std::move(r));
    }
    if (const MethodResult* ref = out.find("clips")) {
      for (auto& r : out.methods) {
        r.rel_plan_length = ref->plan_length > 0 ? r.plan_length / ref->plan_length : 0;
        r.rel_human_cost = ref->human_cost > 0 ? r.human_cost / ref->human_cost : 0;
        r.has_relative = true;
      }
    }
  } catch (const std::exception& e) {
    out.error = e.what();
    out.failure = std::current_exception();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

LiveDecision decide_next_action(const data::Dataset& ds, const data::PlanRecord& observations, lm::LanguageModel& lm,
                                const ExperimentOptions& opts, const std::string& method) {
  if (method != "clips" && method != "lang_only" && method != "action_only")
    throw InputError("--method " + method + " cannot assist from ad-hoc observations (clips, lang_only or action_only)");
  auto task = ds.task(observations.problem_id);
  const DomainFacts df = facts_of(ds.kind());
  inference::InferenceOptions io;
  io.utterance.speaker_rule = opts.speaker_rule;
  io.threads = opts.inference_threads;
  io.utterance_timing = opts.utterance_timing;
  LiveDecision out;
  out.inference = inference::run_inference_on_observations(ds, observations, lm, io);
  const inference::Belief& belief = *out.inference.belief;
  const Modality mod = method == "clips" ? Modality::Both : method == "lang_only" ? Modality::UtteranceOnly
                                                                                   : Modality::ActionOnly;
  const auto& post = out.inference.final_posterior(mod);
  out.goal_posterior = post.goals;

  assist::AssistSetup setup;
  setup.task = task;
  setup.start = belief.state();
  setup.observed_steps = static_cast<int>(out.inference.steps.size()) - 1;
  setup.horizon = df.horizon;
  setup.principal = df.principal;
  setup.assistant = df.assistant;
  setup.noop_cost = df.noop_cost;
  setup.refine = belief.searches();
  setup.qa_floor = opts.qa_floor;
  if (setup.observed_steps >= setup.horizon)
    throw InputError("the observations are " + std::to_string(setup.observed_steps) + " actions long, at or past the "
                     "assistance horizon of " + std::to_string(setup.horizon) + " steps");
  std::vector<assist::Hypothesis> hyps;
  for (size_t h = 0; h < post.hypotheses.size(); ++h)
    hyps.push_back({post.hypotheses[h], std::make_shared<search::Policy>(belief.policies()[h])});
  if (!assist::assistant_turn(setup, setup.start)) {
    out.next_actor = df.principal;
    return out;
  }
  const assist::Decision d = assist::qmdp_decision(setup, hyps, setup.start, setup.observed_steps + 1);
  out.next_actor = df.assistant;
  out.action = task->action_name(d.action);
  return out;
}

}  // namespace clips::eval
