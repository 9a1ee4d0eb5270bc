#include "generate/generate.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "domains/builtin/packs.hpp"
#include "inference/belief.hpp"
#include "inference/temperature.hpp"
#include "inference/utterance_model.hpp"
#include "language/utterance_sampler.hpp"
#include "domains/task_transform.hpp"
#include "pddl/parser.hpp"
#include "pddl/sexpr.hpp"
#include "search/astar.hpp"
#include "search/rtaa.hpp"
#include "util/error.hpp"
#include "util/rng.hpp"

namespace fs = std::filesystem;

namespace clips::generate {

namespace {

// Labels of the random streams (util::Rng::derive).
constexpr uint64_t kProblemStream = 1, kPlanStream = 2;

struct Problem {
  std::string id;
  domains::GeneratedProblem text;
  std::shared_ptr<const pddl::Task> task;
  std::vector<domains::GoalSpec> goals;
};

std::string describe(const GenerateOptions& o) {
  std::string counts;
  for (const auto& [kind, n] : o.map.counts) counts += fmt::format(", {} {}{}", n, kind, n == 1 ? "" : "s");
  return fmt::format("a {}x{} map{}", o.map.width, o.map.height, counts);
}

std::shared_ptr<const pddl::Task> ground(const domains::Pack& pack, const std::shared_ptr<const pddl::Domain>& domain,
                                         const std::string& text, const std::string& path) {
  const bool with_goal = pack.spec().goals.source == domains::GoalSource::ProblemGoal;
  auto problem = std::make_shared<pddl::Problem>(pddl::parse_problem(*domain, text, path, with_goal));
  domains::prepare_problem(pack.spec(), *domain, *problem);
  auto task = std::make_shared<const pddl::Task>(domain, std::move(problem), pack.spec().grounding);
  pack.check_problem(*task, path);
  return task;
}

// The profile plans with `tag` were made with.
model::CostProfile true_profile(const domains::Pack& pack, const std::string& tag) {
  const domains::ProfileSet ps = pack.profiles_for(tag);
  return ps.profiles.at(static_cast<size_t>(ps.true_index));
}

// The first candidate goal A* cannot reach from the start ("" none). A plan
// found with the pack's inference heuristic settles it at once (any plan
// proves reachability, and on large maps optimal A* runs out of nodes on the
// two agents' interleavings); otherwise optimal A* with the admissible
// heuristic decides, as it always did, so small maps are accepted exactly as
// before.
std::string unreachable_goal(const domains::Pack& pack, const Problem& p, const model::CostProfile& costs,
                             size_t max_nodes) {
  const pddl::State s0 = p.task->initial_state();
  const std::string& guide = pack.spec().inference.heuristic;
  for (const auto& g : p.goals) {
    const model::Specification spec(p.task, g.condition, costs);
    search::SearchOptions so;
    so.max_nodes = max_nodes;
    if (!guide.empty()) {
      auto h = pack.make_heuristic(guide, *p.task);
      if (search::plan(spec, *h, s0, so).status == search::SearchStatus::Success) continue;
    }
    auto h = pack.make_heuristic(pack.default_admissible_heuristic(), *p.task);
    const auto r = search::plan(spec, *h, s0, so);
    if (r.status != search::SearchStatus::Success) return g.label + " (" + search::to_string(r.status) + ")";
  }
  return "";
}

// Tags whose assistance options exist in the problem (all tags if none has
// any); packs without tags name plans by their goal (PlanTag rule) or "plan".
std::vector<std::string> usable_tags(const domains::Pack& pack, const pddl::Task& task) {
  const auto& tags = pack.spec().plan_tags;
  std::vector<std::string> out;
  for (const auto& tag : tags)
    for (int o = 0; o < task.num_objects(); ++o)
      if (pack.is_option_object(task, task.object_name(o), tag)) {
        out.push_back(tag);
        break;
      }
  return out.empty() ? tags : out;
}

struct Trajectory {
  std::vector<pddl::ActionId> actions;
  std::vector<pddl::State> states;  // states[t] after t actions
};

// One joint action sequence from Boltzmann(Q / T) of `policy`, or the reason
// it was refused. In the first `passive_steps` steps the assistant does its
// no-op (`noop`, the assistant's wait) instead.
std::optional<Trajectory> sample_trajectory(const pddl::Task& task, search::Policy& policy, bool refine,
                                            const search::SearchOptions& budget,
                                            const std::vector<pddl::CompiledCondition>& other_goals, double temperature,
                                            int max_steps, size_t passive_steps, std::optional<pddl::ActionId> noop,
                                            util::Rng& rng, std::string& why) {
  Trajectory t;
  t.states.push_back(task.initial_state());
  std::vector<double> q, logp, weight;
  while (!policy.spec().is_goal(t.states.back())) {
    if (static_cast<int>(t.actions.size()) >= max_steps) {
      why = fmt::format("no goal within {} steps", max_steps);
      return std::nullopt;
    }
    const pddl::State& s = t.states.back();
    // Refined at every state, the assistant's passive turns too: the
    // observer's model does, so the human acts on the policy
    // inference will hold at that step.
    if (refine) policy.refine_step(s, budget);
    if (noop && t.actions.size() < passive_steps && task.applicable(*noop, s.data())) {
      t.actions.push_back(*noop);
      t.states.push_back(task.apply(s, *noop));
      continue;
    }
    const auto qs = policy.q_values(s);
    q.clear();
    for (const auto& qv : qs) q.push_back(qv.q);
    inference::boltzmann_log_probs(q, temperature, logp);
    weight.clear();
    for (double l : logp) weight.push_back(std::exp(l));
    if (std::none_of(weight.begin(), weight.end(), [](double w) { return w > 0; })) {
      why = "a dead end";
      return std::nullopt;
    }
    const pddl::ActionId a = qs[rng.weighted(weight)].action;
    t.actions.push_back(a);
    t.states.push_back(task.apply(s, a));
  }
  for (const auto& g : other_goals)
    if (g.holds(t.states.back())) {
      why = "reached a second candidate goal";
      return std::nullopt;
    }
  return t;
}

std::string plan_text(const pddl::Task& task, const std::vector<pddl::ActionId>& actions, size_t from, size_t to,
                      std::optional<size_t> utterance_at = std::nullopt, const std::string& utterance = "") {
  std::string out;
  for (size_t i = from; i <= to; ++i) {
    if (utterance_at && *utterance_at == i) out += "; " + utterance + "\n";
    if (i < to) out += task.action_name(actions[i]) + "\n";
  }
  return out;
}

std::string type_name(const pddl::Task& task, const std::string& object) {
  auto o = task.find_object(object);
  return o ? task.domain().types[task.problem().objects[*o].type].name : std::string("object");
}

}  // namespace

GeneratedDataset generate_dataset(const GenerateOptions& options, lm::LanguageModel* lm_in) {
  if (options.problems < 1 || options.plans_per_problem < 1)
    throw InputError("clips generate needs at least one problem and one plan per problem");
  const auto [domain, pack] = domains::load_domain_with_pack(options.domain_file,
                                                             fs::path(options.domain_file).parent_path().string());
  const int max_steps = options.max_steps > 0 ? options.max_steps : pack->roles().horizon;
  GeneratedDataset out;
  out.files["domain.pddl"] = pddl::read_text_file(options.domain_file);

  // ---- problems
  std::vector<Problem> problems;
  const std::string first_tag = pack->spec().plan_tags.empty() ? "" : pack->spec().plan_tags.front();
  for (int p = 1; p <= options.problems; ++p) {
    util::Rng rng(util::Rng::derive(options.seed, {kProblemStream, static_cast<uint64_t>(p)}));
    domains::GenerateParams params = options.map;
    params.problem_name = pack->name() + "-" + std::to_string(p);
    Problem prob;
    prob.id = std::to_string(p);
    std::string last_reason = "no layout fits";
    for (int attempt = 0; attempt < options.problem_attempts && !prob.task; ++attempt) {
      auto drawn = pack->generate_problem(params, rng);
      if (!drawn) continue;
      const std::string path = "problems/" + prob.id + ".pddl";
      Problem candidate;
      candidate.id = prob.id;
      candidate.task = ground(*pack, domain, drawn->pddl, path);
      candidate.text = std::move(*drawn);
      candidate.goals = pack->problem_goals(*candidate.task, path);
      // Reachability does not depend on the costs: any tag's profile will do.
      const std::string bad = unreachable_goal(*pack, candidate, true_profile(*pack, first_tag), options.solvable_nodes);
      if (bad.empty()) prob = std::move(candidate);
      else last_reason = "unsolvable goal " + bad;
    }
    if (!prob.task)
      throw InputError(fmt::format("could not generate {} with every goal solvable in {} attempts (last: {}); try a "
                                   "larger --size or fewer objects",
                                   describe(options), options.problem_attempts, last_reason));
    out.files["problems/" + prob.id + ".pddl"] = prob.text.pddl;
    if (!prob.text.picture.empty()) out.files["problems/" + prob.id + ".txt"] = prob.text.picture;
    problems.push_back(std::move(prob));
  }

  // ---- the speaker's words
  std::shared_ptr<lm::LanguageModel> own_lm;
  if (!lm_in) {
    std::vector<const pddl::Problem*> ps;
    for (const auto& p : problems) ps.push_back(&p.task->problem());
    own_lm = language::make_domain_language_model(options.lm, options.lm_options, *pack, *domain, ps);
  }
  lm::LanguageModel& lm = lm_in ? *lm_in : *own_lm;
  language::UtteranceSampler sampler(pack, domain, lm);
  const auto prior = inference::inverse_gamma_prior(pack->spec().inference.temperature_shape,
                                                    pack->spec().inference.temperature_scale);
  const bool search = pack->spec().inference.search;

  // ---- plans
  nlohmann::json records = nlohmann::json::array();
  for (int p = 1; p <= options.problems; ++p) {
    const Problem& prob = problems[static_cast<size_t>(p - 1)];
    const pddl::Task& task = *prob.task;
    const inference::UtteranceModel speaker(prob.task, pack);
    const auto tags = usable_tags(*pack, task);
    const auto noop = pack->roles().find_noop(task, pack->roles().assistant);
    for (int i = 1; i <= options.plans_per_problem; ++i) {
      util::Rng rng(util::Rng::derive(options.seed, {kPlanStream, static_cast<uint64_t>(p), static_cast<uint64_t>(i)}));
      GeneratedPlan plan;
      plan.problem_id = prob.id;
      const size_t goal = rng.index(prob.goals.size());
      plan.goal = prob.goals[goal].label;
      plan.tag = !tags.empty() ? tags[rng.index(tags.size())]
                 : pack->spec().goals.true_goal == domains::TrueGoalRule::PlanTag ? plan.goal
                                                                                   : std::string("plan");
      plan.id = fmt::format("{}.{}.{}", prob.id, i, plan.tag);
      plan.temperature = options.temperature ? *options.temperature
                                             : inference::temperature_grid()[rng.weighted(prior)];
      auto spec = std::make_shared<const model::Specification>(prob.task, prob.goals[goal].condition,
                                                               true_profile(*pack, plan.tag));
      std::shared_ptr<heuristics::Heuristic> h = pack->make_heuristic(pack->spec().inference.heuristic, task);
      if (!search) h->prepare(*spec, task.initial_state());
      search::Policy policy(spec, h);
      std::vector<pddl::CompiledCondition> others;
      for (size_t g = 0; g < prob.goals.size(); ++g)
        if (g != goal) others.push_back(task.compile_text(prob.goals[g].condition, prob.goals[g].label));

      // The policy as the observer's model holds it at the start (refined once
      // at s_0). Every attempt and the speaker start from a copy of it, so
      // nothing learned on a rejected attempt or later in the sequence
      // shapes an earlier decision.
      search::SearchOptions budget = inference::InferenceOptions{}.refine;
      budget.max_nodes = options.refine_nodes;
      const pddl::State s0 = task.initial_state();
      // A plan that cannot fit into the step limit is refused now, not after
      // every attempt has walked the limit's length (minutes on large maps):
      // with the agents taking turns, the principal's n actions take at
      // least 2n - 1 steps.
      if (const auto n = pack->min_principal_actions(task, s0, plan.goal); n && 2 * *n - 1 > max_steps)
        throw InputError(fmt::format("plan {}: {} needs at least {} actions of the {}, so at least {} steps with the "
                                     "agents taking turns, more than the step limit of {}; give --max-steps {} or more "
                                     "(or a smaller --size)",
                                     plan.id, plan.goal, *n, pack->roles().principal, 2 * *n - 1, max_steps,
                                     2 * *n - 1));
      if (search) policy.refine_step(s0, budget);
      const search::Policy at_start = policy;

      // The observed part: the assistant waits (as in the paper's observed
      // plans, it is passive until the instruction) for k steps, k uniform in
      // 0..2m, m the principal's moves before the first salient action on the
      // policy's greedy joint plan (so the prefix covers about its walk).
      int moves = 0;
      for (pddl::ActionId a : policy.rollout(s0, max_steps)) {
        const auto& ga = task.action(a);
        const std::string& name = task.domain().actions[ga.schema].name;
        if (pack->language().salient_rule(name)) break;
        if (!ga.args.empty() && task.object_name(ga.args[0]) == pack->roles().principal &&
            name != pack->roles().noop_action)
          ++moves;
      }
      const size_t passive = static_cast<size_t>(rng.uniform_int(0, 2 * moves));
      // A sequence in which the assistant never takes an option of the tag
      // is drawn again (the benchmark's precision and recall need its help
      // to be known); after the attempts the last one that reached the goal
      // is kept as it is.
      const auto& the_pack = *pack;  // clang 14 cannot capture a structured binding
      auto helps = [&](const Trajectory& t) {
        for (size_t j = std::min(passive, t.actions.size()); j < t.actions.size(); ++j)
          if (the_pack.option_of(task, t.actions[j], plan.tag)) return true;
        return false;
      };
      std::optional<Trajectory> traj, fallback;
      std::string why;
      for (int attempt = 0; attempt < options.plan_attempts && !traj; ++attempt) {
        policy = at_start;
        traj = sample_trajectory(task, policy, search, budget, others, plan.temperature, max_steps, passive, noop, rng, why);
        if (traj && !helps(*traj)) {
          fallback = std::move(traj);
          traj.reset();
          why = "the assistant took no " + plan.tag + " option";
        }
      }
      if (!traj) traj = std::move(fallback);
      if (!traj)
        throw InputError(fmt::format("plan {}: no sampled action sequence reached {} alone in {} attempts (last: {}); "
                                     "try a lower --temperature or a larger --max-steps",
                                     plan.id, plan.goal, options.plan_attempts, why));
      const auto& acts = traj->actions;
      const size_t L = acts.size();

      // The goal is reached in the completion (its last action), so the split is before it.
      const size_t k = std::min(passive, L - 1);
      // The speaker's plan at step j is the one inference scores an
      // instruction there with (utterance timing "after"): refined at s_0 at
      // the start, then once per step at s_0 .. s_j (the step of a_{k+1}
      // refines at s_k; an instruction after the last observed action is
      // heard in s_k itself). Replayed from the start policy once the
      // sequence is known; the refinements are few next to the sequence's.
      // The instruction's step is drawn among the steps where the joint plan
      // gives the speaker something to ask (a non-empty command set): a
      // speaker with nothing to ask would not speak, and an instruction drawn
      // for no command says nothing of the goal (docs/decisions.md). Only
      // when no step has a command is it drawn among all, with no command.
      std::vector<std::vector<commands::Command>> asks(k + 1);
      std::vector<size_t> can_ask;
      search::Policy speaker_policy = at_start;
      for (size_t j = 0; j <= k; ++j) {
        if (search && j == 1) speaker_policy.refine_step(traj->states[0], budget);
        if (search && j >= 1) speaker_policy.refine_step(traj->states[j], budget);
        asks[j] = speaker.commands_at(speaker_policy, traj->states[j]);
        if (!asks[j].empty()) can_ask.push_back(j);
      }
      const size_t u = can_ask.empty() ? static_cast<size_t>(rng.uniform_int(0, static_cast<int64_t>(k)))
                                       : can_ask[rng.index(can_ask.size())];
      const pddl::State& s_u = traj->states[u];
      const auto& commands = asks[u];
      const commands::Command* command = commands.empty() ? nullptr : &commands[rng.index(commands.size())];
      std::optional<commands::Command> part;
      if (command) {
        auto qualifiers = [&](const std::string& o) { return speaker.qualifiers(o, s_u); };
        auto types = [&](const std::string& o) { return type_name(task, o); };
        part = language::listener_part(*command, pack->language(), qualifiers, types);
      }
      const auto said = sampler.realise(command, /*literal=*/false, task.problem(), rng, part ? &*part : nullptr);
      plan.command = said.command;
      plan.utterance = said.text;
      plan.literal_command = said.command;
      plan.literal_utterance = said.text;
      if (part) {
        const auto literal = sampler.realise(&*part, /*literal=*/true, task.problem(), rng);
        plan.literal_command = literal.command;
        plan.literal_utterance = literal.text;
      }
      plan.observed_steps = static_cast<int>(k);
      plan.completed_steps = static_cast<int>(L - k);
      plan.utterance_step = static_cast<int>(u);
      for (size_t j = k; j < L; ++j)
        if (auto o = pack->option_of(task, acts[j], plan.tag);
            o && std::find(plan.options.begin(), plan.options.end(), *o) == plan.options.end())
          plan.options.push_back(*o);

      out.files["plans/observed/" + plan.id + ".pddl"] = plan_text(task, acts, 0, k, u, plan.utterance);
      out.files["plans/completed/" + plan.id + ".pddl"] = plan_text(task, acts, k, L);
      out.files["utterances/pragmatic/" + plan.id + ".txt"] = plan.utterance + "\n";
      out.files["utterances/literal/" + plan.id + ".txt"] = plan.literal_utterance + "\n";
      records.push_back({{"id", plan.id},
                         {"problem", plan.problem_id},
                         {"goal", plan.goal},
                         {"tag", plan.tag},
                         {"temperature", plan.temperature},
                         {"observed_steps", plan.observed_steps},
                         {"completed_steps", plan.completed_steps},
                         {"utterance_step", plan.utterance_step},
                         {"command", plan.command},
                         {"utterance", plan.utterance},
                         {"utterance_pool", said.pool},
                         {"utterance_candidates", said.candidates},
                         {"utterance_probability", said.probability},
                         {"literal_command", plan.literal_command},
                         {"literal_utterance", plan.literal_utterance},
                         {"assistance_options", plan.options}});
      out.plans.push_back(std::move(plan));
    }
  }

  // What was asked for and what each plan holds (the commands are not in the plan files).
  nlohmann::json summary = {
      {"generator", "clips generate"},
      {"domain", pack->name()},
      {"size", fmt::format("{}x{}", options.map.width, options.map.height)},
      {"counts", options.map.counts},
      {"problems", options.problems},
      {"plans_per_problem", options.plans_per_problem},
      {"seed", options.seed},
      {"temperature", options.temperature ? nlohmann::json(*options.temperature) : nlohmann::json("prior")},
      {"max_steps", max_steps},
      {"max_nodes", options.refine_nodes},  // infer with the same --max-nodes
      {"lm", lm.name()},
      {"plans", records},
  };
  out.files["generation.json"] = summary.dump(2) + "\n";
  return out;
}

void write_dataset(const GeneratedDataset& dataset, const std::string& dir, bool force) {
  std::error_code ec;
  const fs::path root(dir);
  if (fs::exists(root, ec)) {
    if (!fs::is_directory(root, ec)) throw InputError("--out " + dir + " exists and is not a directory");
    if (!fs::is_empty(root, ec)) {
      if (!force) throw InputError("--out " + dir + " is not empty (give --force to replace the dataset there)");
      for (const char* sub : {"problems", "plans", "utterances"}) fs::remove_all(root / sub, ec);
    }
  }
  for (const auto& [rel, content] : dataset.files) {
    const fs::path path = root / rel;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw InputError("cannot create " + path.parent_path().string() + ": " + ec.message());
    std::ofstream f(path, std::ios::binary);
    f << content;
    if (!f) throw InputError("cannot write " + path.string());
  }
}

}  // namespace clips::generate
