#include "eval/methods.hpp"

#include <algorithm>
#include <functional>
#include <mutex>

#include "assist/literal.hpp"
#include "assist/request.hpp"
#include "engine/hypotheses.hpp"
#include "engine/methods.hpp"
#include "engine/policies.hpp"
#include "engine/runs.hpp"
#include "eval/experiment.hpp"
#include "eval/metrics.hpp"
#include "eval/requested.hpp"
#include "commands/utterance_merge.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::eval {

using inference::Modality;

void score_assistance(const PlanContext& ctx, const assist::AssistResult& a, MethodResult& r) {
  r.options = a.options;
  r.precision = assist_precision(a.options, ctx.true_options);
  r.recall = assist_recall(a.options, ctx.true_options);
  r.plan_length = a.plan_length;
  r.human_cost = a.human_cost;
  r.plan_cost = a.plan_cost;
  r.goal_success = a.success;
  r.decision_seconds = a.decision_seconds;
  r.ties = a.ties;
  r.actions = a.plan;
  if (!ctx.plan.requested.empty()) {
    const auto assistant = ctx.task->find_object(ctx.dataset.pack().roles().assistant);
    if (assistant)
      r.request_done = request_done(*ctx.task, ctx.setup.start, *assistant,
                                    parse_requested(*ctx.task, ctx.plan.requested, requested_where(ctx.dataset, ctx.plan)),
                                    a.plan);
  }
  // Printed once, here: the rest of the pipeline keeps action ids.
  for (auto act : a.plan) r.plan.push_back(ctx.task->action_name(act));
}

namespace {

// An OnlineBelief over a copy of the inference belief, read in one modality.
class OnlineAdapter : public assist::OnlineBelief {
 public:
  // `requests`: what the last instruction asked for, per hypothesis (the
  // steps after it hear nothing, so it stays the same).
  OnlineAdapter(const inference::Belief& b, Modality m, std::vector<std::shared_ptr<const assist::Request>> requests)
      : belief_(b), modality_(m), requests_(std::move(requests)) {
    rebuild();
  }
  void observe(const pddl::State& pre, pddl::ActionId a) override {
    // Paper semantics for language-only: no action evidence online.
    if (modality_ == Modality::UtteranceOnly) return;
    belief_.observe(a, pre);
    rebuild();
  }
  std::vector<assist::Hypothesis>& hypotheses() override { return hyps_; }

 private:
  void rebuild() {
    belief_.sync_policies(modality_);  // particle inference: weighted policies up to date
    auto post = belief_.posterior(modality_);
    hyps_ = engine::assistant_hypotheses(belief_, post, requests_, engine::PolicyUse::Share);
  }
  inference::Belief belief_;
  Modality modality_;
  std::vector<std::shared_ptr<const assist::Request>> requests_;
  std::vector<assist::Hypothesis> hyps_;
};

// Goal inference in one modality, then one assistance policy.
class InferenceMethod : public Method {
 public:
  InferenceMethod(std::string name, Modality modality, AssistPolicy policy)
      : Method(std::move(name)), modality_(modality), policy_(policy) {}

  void run(const PlanContext& ctx, MethodResult& r) const override {
    const inference::InferenceRun& inf = ctx.inference;
    const inference::Belief& belief = *inf.belief;
    const auto& post = inf.final_posterior(modality_);
    r.p_true_goal = post.goals.at(inf.true_goal);
    r.goal_posterior = post.goals;
    for (const auto& st : inf.steps) r.posterior_steps.push_back(st[modality_].goals);
    // A method that listens reads what the instruction asked for.
    const auto requests = engine::requests_for(*ctx.task, inf.steps, post.hypotheses.size(), modality_);
    std::vector<assist::Hypothesis> hyps = engine::assistant_hypotheses(belief, post, requests);
    const assist::Decide& decide = engine::decide_of(policy_.decide);
    switch (policy_.episodes) {
      case Episodes::Offline:
        score_assistance(ctx, assist::offline_episode(ctx.setup, hyps, ctx.true_hypothesis, decide), r);
        break;
      case Episodes::PaperMixture:
        score_assistance(ctx, assist::pibar_mdp(ctx.setup, hyps, ctx.true_hypothesis), r);
        break;
      case Episodes::Online: {
        OnlineAdapter online(belief, modality_, requests);
        const domains::Pack& pack = ctx.dataset.pack();
        std::shared_ptr<heuristics::Heuristic> h = pack.make_heuristic(pack.spec().inference.heuristic, *ctx.task);
        if (!ctx.setup.refine) h->prepare(*ctx.true_spec, ctx.setup.start);
        score_assistance(ctx, assist::online_episode(ctx.setup, online, ctx.true_spec, h, decide), r);
        break;
      }
    }
  }

 private:
  Modality modality_;
  AssistPolicy policy_;
};

// The literal listener: the most probable readings of the instruction, then
// planning for them (efficient: as lifted goals; naive: grounded one by one).
class LiteralMethod : public Method {
 public:
  LiteralMethod(std::string name, bool naive) : Method(std::move(name)), naive_(naive) {}

  void run(const PlanContext& ctx, MethodResult& r) const override {
    const data::PlanRecord& p = ctx.plan;
    const pddl::Task& task = *ctx.task;
    const domains::Pack& pack = ctx.dataset.pack();
    const pddl::State& s_T = ctx.setup.start;
    auto lsetup = language::literal_listener_setup(ctx.dataset.pack_ptr());
    std::string utt = p.literal_utterance ? *p.literal_utterance
                      : p.observed.utterances.empty() ? std::string() : p.observed.utterances.back().text;
    if (utt.empty()) throw InputError("plan " + p.id + " has no utterance for the literal listener");
    auto ranked = language::literal_listener(task, s_T, utt, lsetup, ctx.lm);
    if (p.observed.utterances.size() > 1) {
      // Several utterances in one plan: every one is heard in s_T; rankings
      // are merged (most probable prefix of the first, then each later one).
      auto to_cmd = [](const language::ListenerResult& lr) {
        std::vector<commands::RankedCommand> v;
        for (auto& c : lr.commands) v.push_back({c.command, c.prob, c.log_likelihood});
        return v;
      };
      auto kept = commands::probable_prefix(
          to_cmd(language::literal_listener(task, s_T, p.observed.utterances[0].text, lsetup, ctx.lm)));
      for (size_t u = 1; u < p.observed.utterances.size(); ++u)
        kept = commands::combine_utterance_rankings(
            kept, to_cmd(language::literal_listener(task, s_T, p.observed.utterances[u].text, lsetup, ctx.lm)));
      ranked.commands.clear();
      for (auto& k : kept) ranked.commands.push_back({k.command, k.score, k.probability});
    }
    assist::LiteralSetup ls;
    ls.world = ctx.setup;
    ls.truth = ctx.true_spec;
    ls.config = lsetup.config;
    // The assistance searches' node budget (2^16 in bench, as the listener's
    // own default; tiny in `clips validate`'s rehearsal).
    ls.max_nodes = ctx.setup.refine_options.max_nodes;
    auto task_ptr = ctx.task;
    ls.make_heuristic = [&pack, task_ptr]() -> std::shared_ptr<heuristics::Heuristic> {
      return pack.make_heuristic(pack.spec().literal.planning_heuristic, *task_ptr);
    };
    ls.goal_unsatisfiable = pack.goal_unsatisfiable(task);
    ls.truth_policy = std::make_shared<const search::Policy>(ctx.inference.belief->policies()[ctx.true_hypothesis]);
    ls.is_option = [&pack, task_ptr, tag = p.tag](const std::string& o) {
      return pack.is_option_object(*task_ptr, o, tag);
    };
    // Objects per variable type, for grounding lifted commands (naive).
    std::vector<std::string> var_types = pack.spec().literal.variable_types;
    if (var_types.empty())
      for (const auto& t : task.domain().types) var_types.push_back(t.name);
    for (const auto& type : var_types)
      for (auto o : task.objects_of_type(type)) ls.objects_by_type[type].push_back(task.object_name(o));
    // The static qualifier facts the naive grounding checks.
    for (const std::string& qual : pack.language().qualifiers()) {
      auto qpred = task.domain().find_predicate(qual);
      if (!qpred || task.domain().predicates[*qpred].arg_types.size() != 2) continue;
      const auto& types = task.domain().predicates[*qpred].arg_types;
      for (pddl::ObjectId a = 0; a < task.num_objects(); ++a) {
        if (!task.domain().is_subtype(task.problem().objects[a].type, types[0])) continue;
        for (pddl::ObjectId b = 0; b < task.num_objects(); ++b)
          if (task.domain().is_subtype(task.problem().objects[b].type, types[1]) && task.atom(*qpred, {a, b}).value)
            ls.facts.push_back(commands::Term{qual, {task.object_name(a), task.object_name(b)}});
      }
    }
    const uint64_t seed = ctx.options.seed ^ std::hash<std::string>{}(p.id + "/" + name());
    auto lr = assist::literal_assist(ls, ranked, naive_, seed);
    score_assistance(ctx, lr.result, r);
  }

 private:
  bool naive_;
};

// A multimodal chat model reads a picture of s_T and the instruction; its
// failures (endpoint, answer) stay with this method.
class MultimodalMethod : public Method {
 public:
  MultimodalMethod() : Method(baseline_choices().name(Baseline::Multimodal)) {}
  void run(const PlanContext& ctx, MethodResult& r) const override {
    try {
      const inference::Belief& belief = *ctx.inference.belief;
      auto mm = multimodal::run_multimodal(ctx.dataset, ctx.plan, ctx.setup, ctx.inference.goals,
                               belief.policies()[ctx.true_hypothesis], ctx.options.multimodal);
      r.goal_posterior = mm.answer.goal_posterior;
      r.p_true_goal = r.goal_posterior.at(ctx.inference.true_goal);
      r.notes = mm.notes;
      score_assistance(ctx, mm.result, r);
    } catch (const std::exception& e) {
      r.error = e.what();
      r.failure = std::current_exception();
    }
  }
};

}  // namespace

const util::Choices<AssistPolicy>& assist_policy_choices() {
  const auto& live = engine::assistance_choices();
  const std::vector<std::string> qmdp = engine::reserved_policy_names();  // offline, online
  const std::string pibar = live.name(Assistance::PiBar);
  static util::Choices<AssistPolicy> table(
      "assistance method",
      {{{Assistance::QMdp, Episodes::Offline},
        qmdp[0],
        "Q_MDP on the posterior after the observations, kept through the episode, as in the paper",
        {}},
       {{Assistance::QMdp, Episodes::Online}, qmdp[1],
        "Q_MDP, the posterior updated by each action of the episode", {}},
       {{Assistance::PiBar, Episodes::PaperMixture}, pibar, live.help(Assistance::PiBar), {}}});
  // The other registered policies, each decided at every turn on the
  // posterior after the observations. The table changes only when the
  // registrations did (at start-up or in a test's set-up, before readers run:
  // util/choices.hpp); the lock keeps two callers from following them at once.
  static std::mutex follow;
  std::lock_guard<std::mutex> lock(follow);
  std::vector<std::string> gone;
  for (const auto& e : table.entries())
    if (e.value.episodes == Episodes::Offline && e.value.decide != Assistance::QMdp &&
        (!live.contains(e.name) || live.parse(e.name) != e.value.decide))
      gone.push_back(e.name);
  for (const std::string& n : gone) table.remove(n);
  for (const auto& c : live.entries())
    if (c.value != Assistance::QMdp && c.value != Assistance::PiBar && !table.contains(c.name))
      table.add({{c.value, Episodes::Offline}, c.name, c.help + " (decided at each assistant turn, offline)", {}});
  return table;
}

util::Choices<AssistanceSet>& assistance_set_choices() {
  // The help names no policy: the policy table takes entries at run time.
  static util::Choices<AssistanceSet> table(
      "assistance set",
      {{AssistanceSet::Default, "default",
        "each inference method with the first assist policy, under the method's bare name", {}},
       {AssistanceSet::All, "all", "also each inference method with every other assist policy, as METHOD/POLICY",
        {}}});
  return table;
}

util::Choices<Baseline>& baseline_choices() {
  static util::Choices<Baseline> table(
      "baseline", {{Baseline::Multimodal, "multimodal",
                    "a multimodal chat model reads a picture of the state and the instruction", {}}});
  return table;
}

std::string composite_method_name(const std::string& base, AssistPolicy policy) {
  const auto& policies = assist_policy_choices();
  return policy == policies.entries().front().value ? base : base + "/" + policies.name(policy);
}

std::vector<std::string> all_method_names() {
  std::vector<std::string> out;
  for (const std::string& base : engine::posterior_method_names())
    for (const auto& p : assist_policy_choices().entries()) out.push_back(composite_method_name(base, p.value));
  for (const std::string& n : domains::literal_method_choices().names()) out.push_back(n);
  for (const std::string& n : baseline_choices().names()) out.push_back(n);
  return out;
}

std::unique_ptr<Method> make_method(const std::string& name) {
  const auto slash = name.find('/');
  const std::string base = name.substr(0, slash);
  const auto& bases = engine::posterior_method_names();
  if (std::find(bases.begin(), bases.end(), base) != bases.end()) {
    const Modality m = engine::modality_of(clips::parse_method(base));
    const AssistPolicy p = slash == std::string::npos ? assist_policy_choices().entries().front().value
                                                      : assist_policy_choices().parse(name.substr(slash + 1));
    return std::make_unique<InferenceMethod>(name, m, p);
  }
  if (slash == std::string::npos) {
    if (domains::literal_method_choices().contains(base))
      return std::make_unique<LiteralMethod>(
          name, domains::literal_method_choices().parse(base) == domains::LiteralPlanning::Naive);
    if (baseline_choices().contains(base)) switch (baseline_choices().parse(base)) {
        case Baseline::Multimodal: return std::make_unique<MultimodalMethod>();
      }
  }
  throw InputError("unknown method '" + name + "' (known: " + util::or_list(all_method_names()) + ")");
}

}  // namespace clips::eval
