#include "assist/literal.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "commands/grounding.hpp"
#include "commands/sampling.hpp"

namespace clips::assist {

using pddl::ActionId;
using pddl::State;

namespace {

struct TwoPhase {
  std::vector<ActionId> plan;
  int noops = 0;
  size_t command_steps = 0;  // the phase-1 prefix of `plan`
  bool command_ok = false, goal_ok = false;
};

std::vector<commands::Term> as_terms(const pddl::Task& task, const std::vector<ActionId>& plan) {
  std::vector<commands::Term> out;
  for (ActionId a : plan) out.push_back(commands::parse_term(task.action_name(a)));
  return out;
}

TwoPhase two_phase_uncached(const LiteralSetup& ls, const std::string& command_goal);

// Many sampled commands and groundings share goals; plan each goal once.
TwoPhase two_phase(const LiteralSetup& ls, const std::string& command_goal, std::map<std::string, TwoPhase>& cache) {
  auto it = cache.find(command_goal);
  if (it != cache.end()) return it->second;
  TwoPhase tp = two_phase_uncached(ls, command_goal);
  cache.emplace(command_goal, tp);
  return tp;
}

TwoPhase two_phase_uncached(const LiteralSetup& ls, const std::string& command_goal) {
  const AssistSetup& w = ls.world;
  const pddl::Task& task = *w.task;
  int remaining = w.horizon - w.observed_steps;
  TwoPhase out;
  search::SearchOptions so;
  so.max_nodes = ls.max_nodes;
  State end = w.start;
  bool found = false;
  const bool hopeless = ls.goal_unsatisfiable && ls.goal_unsatisfiable(command_goal);
  if (!hopeless) {
    CommandPlan r = command_plan(w.task, command_goal, ls.truth->profile(), w.start, w.principal, ls.make_heuristic, so);
    if (r.status == search::SearchStatus::Success) {
      out.plan = std::move(r.plan);
      // Phase 2 continues from the plan carried out in s_T itself, as the
      // reference does: the human was frozen only to find the plan, and is
      // free to finish (a frozen human could never reach the goal).
      end = pddl::simulate(task, w.start, out.plan).states.back();
      found = true;
    }
  }
  out.command_ok = found && static_cast<int>(out.plan.size()) <= remaining;
  out.command_steps = out.plan.size();
  bool goal_found = false;
  if (static_cast<int>(out.plan.size()) < remaining) {
    State from = model::freeze(task, end, w.assistant);
    auto h = ls.make_heuristic();
    auto r = search::plan(*ls.truth, *h, from, so);
    if (std::getenv("CLIPS_DEBUG_LITERAL"))
      std::fprintf(stderr, "phase2 %s exp=%zu %.3fs\n", search::to_string(r.status).c_str(), r.expanded, r.seconds);
    if (r.status == search::SearchStatus::Success) {
      out.plan.insert(out.plan.end(), r.plan.begin(), r.plan.end());
      goal_found = true;
    }
  }
  if (!goal_found && ls.truth_policy && static_cast<int>(out.plan.size()) < remaining) {
    // Phase 2's search ran out of budget: the principal finishes by its own
    // policy, refined as it goes, with the assistant frozen (it may still
    // wait or hand over what it holds).
    search::Policy principal = *ls.truth_policy;
    State s = model::freeze(task, end, w.assistant);
    while (static_cast<int>(out.plan.size()) < remaining && !ls.truth->is_goal(s)) {
      if (w.refine) principal.refine(s, w.refine_options);
      auto a = principal.value(s) > -model::kInf ? principal.best_action(s) : std::nullopt;
      if (!a) break;
      out.plan.push_back(*a);
      s = task.apply(s, *a);
    }
    goal_found = ls.truth->is_goal(s);
  }
  if (goal_found) {
    out.goal_ok = static_cast<int>(out.plan.size()) <= remaining;
  } else {
    out.noops = std::max(0, remaining - static_cast<int>(out.plan.size()));
  }
  if (static_cast<int>(out.plan.size()) > remaining) out.plan.resize(remaining);
  return out;
}

// The reference's static check of a ground command: it looks at the last
// action only, and rejects the command when that action can never be
// applicable, which is when grounding left it out (a static precondition is
// false, e.g. a key unlocking a door of another colour).
bool last_action_possible(const pddl::Task& task, const commands::GroundCommand& g,
                          const commands::LanguageConfig& config) {
  if (g.actions.empty()) return true;
  return task.find_action(commands::to_pddl(commands::to_agent_names(g.actions.back(), config))).has_value();
}

struct Scored {
  AssistResult r;
  double cmd_ok = 0;
};

Scored score_run(const LiteralSetup& ls, const TwoPhase& tp) {
  Scored s;
  s.r.plan = tp.plan;
  s.r.noops = tp.noops;
  s.r.goal_reached = tp.goal_ok;
  s.r.plan_length = static_cast<double>(tp.plan.size()) + tp.noops;
  s.r.plan_cost = plan_cost(*ls.truth, tp.plan) + tp.noops * ls.world.noop_cost;
  s.r.human_cost = human_cost(*ls.truth, tp.plan, ls.world.principal) + tp.noops * ls.world.noop_cost;
  s.r.success = tp.goal_ok ? 1 : 0;
  s.cmd_ok = tp.command_ok ? 1 : 0;
  return s;
}

}  // namespace

CommandPlan command_plan(const std::shared_ptr<const pddl::Task>& task, const std::string& command_goal,
                         const model::CostProfile& profile, const pddl::State& from, const std::string& principal,
                         const std::function<std::shared_ptr<heuristics::Heuristic>()>& make_heuristic,
                         const search::SearchOptions& options) {
  const model::Specification spec(task, command_goal, profile);
  CommandPlan out;
  for (bool freeze_principal : {false, true}) {
    const State start = freeze_principal ? model::freeze(*task, from, principal) : from;
    auto h = make_heuristic();
    auto r = search::plan(spec, *h, start, options);
    if (std::getenv("CLIPS_DEBUG_LITERAL"))
      std::fprintf(stderr, "phase1 %s frozen=%d %s exp=%zu %.3fs\n", command_goal.c_str(), freeze_principal,
                   search::to_string(r.status).c_str(), r.expanded, r.seconds);
    out.status = r.status;
    if (r.status == search::SearchStatus::Success) {
      out.plan = std::move(r.plan);
      break;
    }
  }
  return out;
}

LiteralRun literal_assist(const LiteralSetup& ls, const language::ListenerResult& ranked, bool naive, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::map<std::string, TwoPhase> cache;
  LiteralRun out;
  AssistResult& mean = out.result;
  std::vector<double> probs;
  for (auto& c : ranked.commands) probs.push_back(c.prob);
  if (probs.empty()) {
    mean.noops = ls.world.horizon - ls.world.observed_steps;
    mean.plan_length = mean.noops;
    mean.plan_cost = mean.human_cost = mean.noops * ls.world.noop_cost;
    return out;
  }
  std::uniform_real_distribution<double> u(0.0, 1.0 / ls.samples);
  auto samples = commands::systematic_sample(probs, u(rng), static_cast<size_t>(ls.samples));
  double best_w = -1;
  for (const auto& smp : samples) {
    const commands::Command& cmd = ranked.commands[smp.index].command;
    Scored agg;
    std::map<std::string, double> options;
    if (!naive) {
      TwoPhase tp = two_phase(ls, cmd.to_goal_formula(ls.config), cache);
      agg = score_run(ls, tp);
      // Options: objects bound to the command's focal variables in the phase-1 plan.
      std::vector<ActionId> cmd_part(tp.plan.begin(),
                                     tp.plan.begin() + static_cast<long>(std::min(tp.command_steps, tp.plan.size())));
      for (auto& o : commands::match_focal_objects(cmd, as_terms(*ls.world.task, cmd_part), ls.config))
        if (ls.is_option(o)) options[o] = 1.0;
    } else {
      auto groundings = commands::naive_groundings(cmd, ls.objects_by_type, ls.facts);
      for (auto& g : groundings)
        for (auto& o : commands::focal_objects(g.actions, ls.config))
          if (ls.is_option(o)) options[o] += 1.0 / static_cast<double>(groundings.size());
      // Plans only for groundings that are not statically impossible.
      std::erase_if(groundings, [&](const commands::GroundCommand& g) {
        return !last_action_possible(*ls.world.task, g, ls.config);
      });
      if (groundings.size() > 10) {
        std::shuffle(groundings.begin(), groundings.end(), rng);
        groundings.resize(10);
      }
      if (groundings.empty()) {
        agg.r.noops = ls.world.horizon - ls.world.observed_steps;
        agg.r.plan_length = agg.r.noops;
        agg.r.plan_cost = agg.r.human_cost = agg.r.noops * ls.world.noop_cost;
      }
      for (auto& g : groundings) {
        commands::Command ground;
        ground.actions = g.actions;
        ground.predicates = g.predicates;
        Scored s = score_run(ls, two_phase(ls, ground.to_goal_formula(ls.config), cache));
        double k = 1.0 / static_cast<double>(groundings.size());
        agg.r.plan_length += k * s.r.plan_length;
        agg.r.plan_cost += k * s.r.plan_cost;
        agg.r.human_cost += k * s.r.human_cost;
        agg.r.success += k * s.r.success;
        agg.cmd_ok += k * s.cmd_ok;
        if (agg.r.plan.empty()) agg.r.plan = s.r.plan;
      }
    }
    double w = smp.weight;
    mean.plan_length += w * agg.r.plan_length;
    mean.plan_cost += w * agg.r.plan_cost;
    mean.human_cost += w * agg.r.human_cost;
    mean.success += w * agg.r.success;
    out.command_success += w * agg.cmd_ok;
    for (auto& [o, p] : options) mean.options[o] += w * p;
    if (w > best_w) {
      best_w = w;
      mean.plan = agg.r.plan;
      mean.noops = agg.r.noops;
    }
  }
  mean.goal_reached = mean.success >= 0.5;
  return out;
}

}  // namespace clips::assist
