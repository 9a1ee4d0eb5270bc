#include "app/observations.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "pddl/plan.hpp"
#include "pddl/sexpr.hpp"
#include "util/error.hpp"
#include "util/utf8.hpp"

namespace clips::app {

namespace {

bool blank(const std::string& s) { return s.find_first_not_of(" \t\r\n\f\v") == std::string::npos; }

// Inline actions start with '('; anything else names a plan file.
bool is_inline(const std::string& actions) {
  const size_t a = actions.find_first_not_of(" \t\r\n");
  return a != std::string::npos && actions[a] == '(';
}

pddl::PlanFile inline_actions(const std::string& text) {
  pddl::PlanFile pf;
  pf.path = "--actions";
  for (const pddl::SExpr& e : pddl::read_sexprs(text, "--actions")) {
    if (!e.is_list) throw InputError(e.loc, "expected an action like (move human left), found '" + e.str() + "'");
    pf.actions.push_back({e.str(), e.loc});
  }
  return pf;
}

pddl::PlanFile actions_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError("--actions " + path + ": no such file (inline actions start with '(', e.g. \"(move human up)\")");
  return pddl::load_plan(path);  // reports a directory or an unreadable file
}

// The plan tag of --condition: one of the pack's plan_tags (its first when
// none is given); a pack without tags takes none.
std::string condition_tag(const domains::Pack& pack, const std::string& condition) {
  const auto& tags = pack.spec().plan_tags;
  if (tags.empty()) {
    if (condition.empty()) return "";
    throw UsageError("--condition " + condition + ": the " + pack.name() +
                     " pack declares no plan tags (pack.json plan_tags), so there is no condition to choose");
  }
  if (condition.empty()) return tags.front();
  if (std::find(tags.begin(), tags.end(), condition) == tags.end()) {
    std::string known;
    for (const auto& t : tags) known += (known.empty() ? "" : ", ") + t;
    throw UsageError("--condition: unknown plan tag '" + condition + "' of the " + pack.name() + " pack (known: " +
                     known + ")");
  }
  return condition;
}

}  // namespace

void add_observation_options(CLI::App* cmd, ObservationFlags& f) {
  cmd->add_option("--plan", f.plan, "Observed plan id in the dataset, e.g. 2.1.keys (or give --problem)");
  cmd->add_option("--problem", f.problem,
                  "Instead of --plan: a problem id of the dataset (e.g. 2); the observations are --actions and "
                  "--utterance, the candidate goals those of the problem");
  cmd->add_option("--actions", f.actions,
                  "With --problem: the observed actions. A value starting with '(' is inline PDDL action terms, "
                  "e.g. \"(move human right) (pickup human key1)\"; anything else names a plan file with one action "
                  "per line (and '; <utterance>' lines, as in the dataset's plans/observed/)");
  cmd->add_option("--utterance", f.utterance, "With --problem: what the human said (UTF-8 text)");
  cmd->add_option("--utterance-step", f.utterance_step,
                  "With --utterance: the number of actions done before it was said (default 0: before the first)")
      ->check(NonNegativeInteger);
  // The names are the pack's (pack.json plan_tags), known once the dataset is read.
  cmd->add_option("--condition", f.condition,
                  "With --problem, for a pack that declares plan tags: the tag the observations are read under, "
                  "which picks the cost profiles the human may have (doors-keys-gems: the paper's two conditions; an "
                  "unknown tag's error lists the pack's); default: the pack's first");
}

void check_observation_flags(const ObservationFlags& f) {
  if (!f.plan.empty() && !f.problem.empty()) throw UsageError("give --plan or --problem, not both");
  if (f.plan.empty() && f.problem.empty())
    throw UsageError("give --plan ID (a dataset plan) or --problem P with --actions and/or --utterance");
  const bool adhoc = !f.actions.empty() || f.utterance || f.utterance_step;
  if (!f.plan.empty() && adhoc)
    throw UsageError("--actions, --utterance and --utterance-step go with --problem; --plan " + f.plan +
                     " brings its own observations");
  if (f.plan.empty() && f.actions.empty() && !f.utterance)
    throw UsageError("--problem " + f.problem + " needs observations: --actions and/or --utterance");
  if (f.utterance_step && !f.utterance) throw UsageError("--utterance-step needs --utterance");
  if (!f.plan.empty() && !f.condition.empty())
    throw UsageError("--condition goes with --problem; --plan " + f.plan + " brings its own");
  if (f.utterance) {
    if (blank(*f.utterance)) throw UsageError("--utterance is empty");
    if (auto bad = util::utf8_problem(*f.utterance); !bad.empty()) throw InputError("--utterance is " + bad);
  }
  if (!f.problem.empty() && blank(f.actions) && !f.actions.empty()) throw UsageError("--actions is empty");
}

data::PlanRecord observations_record(const data::Dataset& ds, const ObservationFlags& f) {
  std::error_code ec;
  if (!std::filesystem::exists(ds.problem_path(f.problem), ec)) {
    std::vector<std::string> ids;
    for (const auto& p : ds.plans())
      if (std::find(ids.begin(), ids.end(), p.problem_id) == ids.end()) ids.push_back(p.problem_id);
    std::string known;
    for (const auto& id : ids) known += (known.empty() ? "" : ", ") + id;
    throw InputError("--problem " + f.problem + ": no file problems/" + f.problem + ".pddl in " + ds.dir() +
                     (known.empty() ? "" : " (problems with plans: " + known + ")"));
  }
  data::PlanRecord rec;
  rec.id = "problem " + f.problem + " (observations given on the command line)";
  rec.problem_id = f.problem;
  rec.tag = condition_tag(ds.pack(), f.condition);
  if (!f.actions.empty()) rec.observed = is_inline(f.actions) ? inline_actions(f.actions) : actions_file(f.actions);
  rec.observed.path = f.actions.empty() ? "--utterance" : rec.observed.path;

  // Every action must name known objects and be applicable where it is taken.
  auto task = ds.task(f.problem);
  pddl::State s = task->initial_state();
  const size_t n = rec.observed.actions.size();
  for (size_t k = 0; k < n; ++k) {
    const pddl::PlanLine& line = rec.observed.actions[k];
    pddl::ActionId a;
    try {
      a = pddl::resolve_step(*task, line, s);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{} (action {} of {} in --actions)", e.what(), k + 1, n));
    }
    s = task->apply(s, a);
  }
  if (f.utterance) {
    const int step = f.utterance_step.value_or(0);
    if (step > static_cast<int>(n))
      throw InputError(fmt::format("--utterance-step {} is past the last action ({} given)", step, n));
    rec.observed.utterances.push_back({*f.utterance, step, SourceLoc{"--utterance", 0, 0}});
    std::stable_sort(rec.observed.utterances.begin(), rec.observed.utterances.end(),
                     [](const auto& a, const auto& b) { return a.index < b.index; });
  }
  for (const auto& u : rec.observed.utterances) {
    if (blank(u.text)) throw InputError(u.loc, "empty utterance");
    if (auto bad = util::utf8_problem(u.text); !bad.empty()) throw InputError(u.loc, "utterance is " + bad);
  }
  if (const int most = ds.pack().spec().max_utterances_per_plan;
      most > 0 && static_cast<int>(rec.observed.utterances.size()) > most)
    throw InputError(fmt::format("a {} observation holds at most {} utterance(s) (the model hears that many); got {} "
                                 "(--utterance and '; ' lines of --actions)",
                                 ds.pack().name(), most, rec.observed.utterances.size()));
  if (rec.observed.actions.empty() && rec.observed.utterances.empty())
    throw InputError("--actions " + f.actions + " holds no action and no utterance");
  return rec;
}

}  // namespace clips::app
