// `clips plan`: optimal A* (or RTAA*) for one goal and cost profile.
#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/choice_option.hpp"
#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "data/dataset.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "domains/task_transform.hpp"
#include "pddl/parser.hpp"
#include "pddl/sexpr.hpp"
#include "search/planners.hpp"
#include "search/rtaa.hpp"
#include "util/memory.hpp"

namespace clips::app {

namespace {

// A goal with nothing to achieve: "()" or "(and)".
bool is_empty_goal(const pddl::SExpr& e) {
  if (!e.is_list) return false;
  if (e.items.empty()) return true;
  if (e.head() != "and") return false;
  for (size_t i = 1; i < e.items.size(); ++i)
    if (!is_empty_goal(e.items[i])) return false;
  return true;
}

constexpr double kRtaaTimeLimit = 60;  // default --time-limit for rtaa runs

}  // namespace

void register_plan(CLI::App& app) {
  auto* cmd = app.add_subcommand("plan", "Plan for a goal with A* (optimal with an admissible heuristic) or RTAA*");
  struct Opts {
    std::string dataset, problem, domain_file, problem_file, goal, costs, heuristic, from_plan;
    std::string planner = search::planner_choices().name(search::Planner::AStar);
    bool json = false;
    bool ground_only = false;
    size_t max_nodes = size_t{1} << 24;
    double max_seconds = 300;
    int max_steps = 200;
    std::optional<double> time_limit;
    int64_t max_ground_actions = pddl::GroundingOptions::kDefaultMaxGroundActions;
    std::optional<double> max_memory_mib;
    double weight = 1;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (with domain.pddl and problems/)");
  cmd->add_option("--problem", o->problem, "Problem id in the dataset (e.g. 2), or with --domain a problem file");
  cmd->add_option("--domain", o->domain_file, "A PDDL domain file (instead of --dataset)");
  auto* goal_opt = cmd->add_option("--goal", o->goal,
                                   "Goal condition in PDDL, e.g. \"(has human gem1)\" (default: the problem's goal)");
  cmd->add_option("--costs", o->costs,
                  "Cost profile: 1..4 for doors-keys-gems (C1..C4, default 1), 'unit', or 'task' (the domain's "
                  "action costs; default for other domains when they declare total-cost)");
  add_choice_option(cmd, "--planner", o->planner, search::planner_choices(), "Planner (default astar)");
  cmd->add_option("--heuristic", o->heuristic, "Heuristic name (default: the domain's admissible one)");
  cmd->add_option("--from-plan", o->from_plan, "Start from the end of this observed plan (dataset plan id)");
  cmd->add_option("--max-nodes", o->max_nodes,
                  "Expansion budget of each A* search (default 2^24); RTAA* runs one search per successor and "
                  "executed action, each with this budget")
      ->check(PositiveInteger);
  cmd->add_option("--max-seconds", o->max_seconds,
                  "Time budget of each A* search (default 300); not a limit on the whole RTAA* run: see --time-limit")
      ->check(PositiveSeconds);
  cmd->add_option("--max-steps", o->max_steps, "RTAA*: maximum number of executed actions (default 200)")
      ->check(PositiveInteger);
  cmd->add_option("--time-limit", o->time_limit,
                  fmt::format("Wall-clock limit for the whole run, all searches included (default {:g} s for rtaa; "
                              "astar: only --max-seconds)",
                              kRtaaTimeLimit))
      ->check(PositiveSeconds);
  cmd->add_option("--max-ground-actions", o->max_ground_actions,
                  fmt::format("Refuse to ground a task that may have more ground actions than this (default {}; "
                              "each takes about a kilobyte; grounding also stops before memory runs out)",
                              pddl::GroundingOptions::kDefaultMaxGroundActions))
      ->check(CLI::Range(int64_t{1}, int64_t{1} << 40));
  cmd->add_option("--max-memory", o->max_memory_mib,
                  "Stop searching when the process holds more than this many MiB (default: 3/4 of the memory "
                  "left when the run starts: the machine's, the ulimit's or the cgroup's, whichever is least)")
      ->check(CLI::Range(1.0, 1e9));
  cmd->add_option("--weight", o->weight,
                  "Weighted A* (f = g + W h): W > 1 finds plans faster on hard goals, at most W times the optimal "
                  "cost with an admissible heuristic (default 1: optimal)")
      ->check(CLI::Range(1.0, 1e6));
  cmd->add_flag("--json", o->json, "Print one JSON object: plan, cost, expanded, seconds, status");
  cmd->add_flag("--ground-only", o->ground_only,
                "Parse and ground the task, print its size (atoms, fluents, actions, axioms) and stop: no search");
  cmd->callback([o, goal_opt] {
    using clock = std::chrono::steady_clock;
    const bool astar = search::planner_choices().parse(o->planner) == search::Planner::AStar;
    const auto t_run = clock::now();
    const double time_limit = o->time_limit ? *o->time_limit
                              : astar       ? std::numeric_limits<double>::infinity()
                                            : kRtaaTimeLimit;
    // The run's deadline, set before anything is read, so grounding counts
    // too: --time-limit, and for A* (one search) also --max-seconds.
    auto after = [&](double secs) {
      return secs < 1e9 ? t_run + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(secs))
                        : clock::time_point::max();  // beyond that: no limit (and no time_point overflow)
    };
    data::GroundingLimits limits(o->max_ground_actions);
    limits.deadline = after(time_limit);
    limits.deadline_label = fmt::format("time limit of {:g} s", time_limit);
    if (astar && o->max_seconds < time_limit) {
      limits.deadline = after(o->max_seconds);
      limits.deadline_label = fmt::format("--max-seconds limit of {:g} s", o->max_seconds);
    }
    int64_t max_memory = std::numeric_limits<int64_t>::max();
    if (o->max_memory_mib) {
      max_memory = static_cast<int64_t>(*o->max_memory_mib * 1024 * 1024);
    } else if (auto room = util::memory_headroom()) {
      max_memory = util::resident_bytes() + room->bytes / 4 * 3;
    }
    if (goal_opt->count() > 0 && o->goal.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
      throw InputError("--goal is empty (omit it to plan for the problem's goal)");
    if (o->domain_file.empty() && (!o->dataset.empty() || std::getenv("CLIPS_DATASET")))
      o->dataset = dataset_dir(o->dataset);
    std::shared_ptr<const pddl::Task> task;
    domains::PackPtr pack;
    pddl::State start;
    if (!o->dataset.empty()) {
      if (o->problem.empty() && o->from_plan.empty()) throw InputError("--problem or --from-plan is required with --dataset");
      // A plan's files only when one is asked for.
      auto ds = o->from_plan.empty() ? data::Dataset::load_problems(o->dataset) : data::Dataset::load(o->dataset);
      ds.set_grounding_limits(limits);
      pack = ds.pack_ptr();
      if (!o->from_plan.empty()) {
        const auto& p = ds.plan(o->from_plan);
        if (!o->problem.empty() && o->problem != p.problem_id)
          throw InputError("plan " + p.id + " is on problem " + p.problem_id + ", not " + o->problem);
        task = ds.task(p.problem_id);
        start = pddl::simulate(*task, task->initial_state(), p.observed).states.back();
      } else {
        task = ds.task(o->problem);
        start = task->initial_state();
      }
    } else {
      if (o->domain_file.empty() || o->problem.empty())
        throw InputError("give --dataset DIR --problem ID, or --domain FILE --problem FILE");
      // A pack.json beside the domain file, or the shared/built-in pack of its
      // name; the domain as that pack has clips ground it.
      auto [d, found] = domains::load_domain_with_pack(o->domain_file,
                                                       std::filesystem::path(o->domain_file).parent_path().string());
      pack = found;
      auto p = std::make_shared<pddl::Problem>(pddl::load_problem(*d, o->problem));
      domains::prepare_problem(pack->spec(), *d, *p);
      pddl::GroundingOptions go = pack->spec().grounding;
      limits.apply(go);
      task = std::make_shared<pddl::Task>(d, p, go);
      start = task->initial_state();
    }
    if (o->ground_only) {
      const double secs = std::chrono::duration<double>(clock::now() - t_run).count();
      if (o->json) {
        nlohmann::json j;
        j["status"] = "grounded";
        j["atoms"] = task->num_atoms();
        j["fluents"] = task->num_fluents();
        j["actions"] = task->num_actions();
        j["axioms"] = task->num_axioms();
        j["seconds"] = secs;
        fmt::print("{}\n", j.dump());
      } else {
        fmt::print("; grounded: {} atoms, {} fluents, {} actions, {} axioms, {:.3f} s\n", task->num_atoms(),
                   task->num_fluents(), task->num_actions(), task->num_axioms(), secs);
      }
      g_exit_code = kExitOk;
      return;
    }
    std::string goal = o->goal;
    if (goal.empty()) {
      if (!task->problem().goal_sexpr) throw InputError("--goal is required (the problem has no :goal)");
      goal = task->problem().goal_sexpr->str();
    }
    if (is_empty_goal(pddl::read_one_sexpr(goal, "--goal")))
      throw InputError("goal " + goal + " is empty: give at least one condition, e.g. \"(has human gem1)\"");
    std::string costs = o->costs;
    // A problem's :metric is what its plans cost.
    if (costs.empty())
      costs = !pack->spec().default_cost_profile.empty()                ? pack->spec().default_cost_profile
              : task->domain().total_cost || task->problem().metric ? "task"
                                                                        : "unit";
    auto spec = std::make_shared<model::Specification>(task, goal, pack->cost_profile(costs));
    std::string hname = o->heuristic.empty() ? pack->default_admissible_heuristic() : o->heuristic;
    std::shared_ptr<heuristics::Heuristic> h = pack->make_heuristic(hname, *task);
    search::SearchOptions so;
    so.max_nodes = o->max_nodes;
    so.max_seconds = o->max_seconds;
    so.deadline = after(time_limit);
    so.max_memory_bytes = max_memory;
    so.h_weight = o->weight;
    if (astar) so.deadline = std::min(so.deadline, after(o->max_seconds));
    auto out_of_time = [&] { return clock::now() >= after(time_limit); };
    // What finds a plan for a hard goal (e.g. every gem of mDKG problem 2: 0.1 s
    // against 16.7 million expansions for optimal A*), at the price of optimality.
    const std::string try_weight =
        o->weight == 1 ? "; for a plan that may not be optimal, try --heuristic hff --weight 5" : "";
    std::vector<pddl::ActionId> plan;
    double cost = 0, seconds = 0;
    size_t expanded = 0;
    std::string status;
    if (astar) {
      auto r = search::plan(*spec, *h, start, so);
      plan = r.plan;
      cost = r.status == search::SearchStatus::Success ? r.cost : 0;
      expanded = r.expanded;
      seconds = r.seconds;
      status = search::to_string(r.status);
      // A budget stop is not an answer: say which limit ended the search, so
      // it is never read as "no plan exists" (status failure).
      if (r.status == search::SearchStatus::MaxTime && out_of_time()) {
        status = "time_limit";
        fmt::print(stderr, "plan: stopped: time limit of {:g} s reached after {} expanded nodes\n", time_limit,
                   expanded);
      } else if (r.status == search::SearchStatus::MaxTime) {
        fmt::print(stderr,
                   "plan: stopped: --max-seconds limit of {:g} s reached after {} expanded nodes; no plan found "
                   "within the limit (that is not a proof that none exists){}\n",
                   o->max_seconds, expanded, try_weight);
      } else if (r.status == search::SearchStatus::MaxNodes) {
        fmt::print(stderr,
                   "plan: stopped: --max-nodes limit of {} expansions reached; no plan found within the limit "
                   "(that is not a proof that none exists){}\n",
                   o->max_nodes, try_weight);
      } else if (r.status == search::SearchStatus::MaxMemory) {
        fmt::print(stderr,
                   "plan: stopped: memory limit of {} reached after {} expanded nodes (--max-memory); no plan found "
                   "within the limit (that is not a proof that none exists){}\n",
                   util::format_bytes(max_memory), expanded, try_weight);
      } else if (r.status == search::SearchStatus::Failure) {
        fmt::print(stderr, "plan: no plan exists: the goal cannot be reached from the start state ({} expanded nodes)\n",
                   expanded);
      }
    } else {
      auto t0 = clock::now();
      search::Policy pol(spec, h);
      pddl::State s = start;
      status = "max_steps";
      for (int i = 0; i < o->max_steps; ++i) {
        if (spec->is_goal(s)) break;
        if (out_of_time()) {
          status = "time_limit";
          break;
        }
        auto st = pol.refine(s, so);
        expanded += st.expanded;
        if (out_of_time()) {  // the last refine was cut short: do not act on it
          status = "time_limit";
          break;
        }
        if (util::resident_bytes() > max_memory) {
          status = "max_memory";
          break;
        }
        auto a = pol.best_action(s);
        if (!a) {
          status = "failure";
          break;
        }
        plan.push_back(*a);
        cost += spec->cost(*a);
        s = task->apply(s, *a);
      }
      if (spec->is_goal(s)) status = "success";
      seconds = std::chrono::duration<double>(clock::now() - t0).count();
      if (status == "time_limit")
        fmt::print(stderr, "plan: stopped: time limit of {:g} s reached after {} actions\n", time_limit, plan.size());
      if (status == "max_memory") {
        fmt::print(stderr, "plan: stopped: memory limit of {} reached after {} actions (--max-memory)\n",
                   util::format_bytes(max_memory), plan.size());
      }
    }
    if (o->json) {
      nlohmann::json j;
      j["plan"] = nlohmann::json::array();
      for (auto a : plan) j["plan"].push_back(task->action_name(a));
      j["cost"] = cost;
      j["expanded"] = expanded;
      j["seconds"] = seconds;
      j["status"] = status;
      j["goal"] = goal;
      j["costs"] = spec->profile().name;
      j["heuristic"] = hname;
      j["weight"] = o->weight;
      fmt::print("{}\n", j.dump());
    } else {
      for (auto a : plan) fmt::print("{}\n", task->action_name(a));
      fmt::print("; status {}, cost {:.10g}, {} actions, {} expanded, {:.3f} s ({} heuristic, costs {})\n", status, cost,
                 plan.size(), expanded, seconds, hname, spec->profile().name);
    }
    // "failure" is a finished search (A*: the goal is unreachable; RTAA*: a dead end); anything else
    // that is not a success ran out of a budget.
    g_exit_code = status == "success" ? kExitOk : status == "failure" ? kExitUnsolvable : kExitLimit;
  });
}

}  // namespace clips::app
