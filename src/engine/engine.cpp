#include "engine/engine.hpp"
#include "domains/builtin/packs.hpp"
#include "engine/hypotheses.hpp"
#include "engine/options.hpp"
#include "engine/policies.hpp"
#include "engine/runs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <utility>

#include <fmt/core.h>

#include "assist/assist.hpp"
#include "assist/literal.hpp"
#include "assist/request.hpp"
#include "assist/setup.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "search/astar.hpp"
#include "util/error.hpp"

namespace clips::engine {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using inference::Modality;

namespace {

// ---- per-call bounds ------------------------------------------------------------

std::string seconds_text(double s) { return fmt::format("{:g} s", s); }

class Bounds {
 public:
  explicit Bounds(const CallLimits& limits) : limits_(limits) {
    if (std::isnan(limits.seconds) || limits.seconds < 0)
      throw InputError("the time limit must be a number of seconds >= 0, not " + fmt::format("{}", limits.seconds));
    // Beyond about 30 years: no limit (and no time_point overflow).
    if (limits.seconds < 1e9)
      deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.seconds));
  }
  Clock::time_point deadline() const { return deadline_; }
  bool stop_requested() const { return limits_.cancel && limits_.cancel->load(); }
  // The belief's stop test (null when the call cannot be cancelled).
  std::function<bool()> stop_test() const {
    if (!limits_.cancel) return {};
    return [this] { return stop_requested(); };
  }
  [[noreturn]] void cancelled() const {
    throw CancelledError("the call was cancelled; the session is as it was before the call");
  }
  void check_cancel() const {
    if (stop_requested()) cancelled();
  }
  // After the work: a search cut at the deadline leaves partial values, so
  // the whole call counts as stopped.
  void check_deadline() const {
    if (deadline_ != Clock::time_point::max() && Clock::now() >= deadline_)
      throw TimeLimitError("the time limit of " + seconds_text(limits_.seconds) +
                           " was reached; the session is as it was before the call");
  }
  void check() const {
    check_cancel();
    check_deadline();
  }

 private:
  const CallLimits& limits_;
  Clock::time_point deadline_ = Clock::time_point::max();
};

// ---- language models --------------------------------------------------------------

// Language models are thread-safe and slow to build (the embedded one trains
// or loads its parameters), so engines with the same settings share one.
std::shared_ptr<lm::LanguageModel> shared_language_model(const LanguageModelOptions& o) {
  static std::mutex mu;
  static std::map<std::string, std::weak_ptr<lm::LanguageModel>> models;
  const std::string key = o.backend + '\n' + o.base_url + '\n' + o.model + '\n' + std::to_string(o.timeout_seconds);
  std::lock_guard<std::mutex> lock(mu);
  if (auto m = models[key].lock()) return m;
  language::LanguageModelOptions lo;
  lo.base_url = o.base_url;
  lo.model = o.model;
  lo.timeout_seconds = o.timeout_seconds;
  std::shared_ptr<lm::LanguageModel> m = language::make_language_model(o.backend, lo);
  models[key] = m;
  return m;
}

// A session on a dataset's problem hears as `clips infer` and `clips serve`
// do on that dataset (language::make_dataset_language_model), one model per
// folder; `dataset` is called only to build it (null: no such dataset).
std::shared_ptr<lm::LanguageModel> dataset_language_model(
    const LanguageModelOptions& o, const std::string& dir,
    const std::function<std::shared_ptr<const data::Dataset>()>& dataset) {
  if (o.backend != "embedded") return shared_language_model(o);
  static std::mutex mu;
  static std::map<std::string, std::weak_ptr<lm::LanguageModel>> models;
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(dir, ec);
  const std::string key = ec ? dir : canonical.string();
  std::lock_guard<std::mutex> lock(mu);
  if (auto m = models[key].lock()) return m;
  const auto ds = dataset();
  if (!ds) return nullptr;
  std::shared_ptr<lm::LanguageModel> m = language::make_dataset_language_model(o.backend, {}, *ds);
  models[key] = m;
  return m;
}

// The dataset folder a problem file belongs to (DIR/problems/P.pddl, with
// DIR/domain.pddl and recorded plans in DIR/plans/observed), if any.
std::optional<std::string> dataset_folder_of(const pddl::Problem& problem) {
  if (problem.file.empty()) return std::nullopt;
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(problem.file, ec);
  if (ec || file.parent_path().filename() != "problems") return std::nullopt;
  const fs::path dir = file.parent_path().parent_path();
  if (!fs::exists(dir / "domain.pddl", ec) || !fs::is_directory(dir / "plans" / "observed", ec)) return std::nullopt;
  return dir.string();
}

// The model an engine hears with: for the embedded backend, the one `clips
// infer` and `clips serve` use on this domain (trained on the pack's corpora,
// else on a corpus generated from the domain, its problem and its goals);
// shared by engines on the same domain, problem and goals.
std::shared_ptr<lm::LanguageModel> engine_language_model(const LanguageModelOptions& o, const domains::Pack& pack,
                                                         const pddl::Task& task,
                                                         const std::vector<std::string>& goal_labels) {
  if (o.backend != "embedded") return shared_language_model(o);
  // A problem of a dataset folder, opened as a file (Session::open_domain,
  // `clips assist --problem`), hears as the dataset's sessions do.
  if (const auto dir = dataset_folder_of(task.problem())) {
    auto m = dataset_language_model(o, *dir, [&]() -> std::shared_ptr<const data::Dataset> {
      auto ds = std::make_shared<const data::Dataset>(data::Dataset::load(*dir));
      return ds->pack().name() == pack.name() ? ds : nullptr;
    });
    if (m) return m;
  }
  static std::mutex mu;
  static std::map<std::string, std::weak_ptr<lm::LanguageModel>> models;
  // A problem read from a file is known by its path; one sent as text is not
  // shared (its text is not kept).
  const pddl::Problem& problem = task.problem();
  std::string key = pack.name() + '\n' + task.domain().name + '\n' + problem.file + '\n' + problem.name + '\n' +
                    std::to_string(problem.objects.size()) + '\n' + std::to_string(problem.init_atoms.size());
  for (const auto& g : goal_labels) key += '\n' + g;
  const bool shared = !problem.file.empty();
  std::lock_guard<std::mutex> lock(mu);
  if (shared)
    if (auto m = models[key].lock()) return m;
  std::shared_ptr<lm::LanguageModel> m =
      language::make_domain_language_model(o.backend, {}, pack, task.domain(), {&task.problem()}, goal_labels);
  if (shared) models[key] = m;
  return m;
}

void check_backend(const std::string& backend) { language::language_model_choices().parse(backend); }

inference::InferenceOptions inference_options(const SessionOptions& o) {
  inference::InferenceOptions io;
  io.refine.max_nodes = o.max_nodes;
  io.refine.max_seconds = o.search_seconds;
  io.threads = o.threads;
  io.assistant_turns = inference::parse_assistant_turns(o.assistant_turns);
  apply_particle_options(o, io);
  return io;
}

// "(move human left)" -> "human": the acting agent is the first argument.
std::string agent_of(const std::string& action) {
  const auto sp = action.find(' '), end = action.find_first_of(" )", sp + 1);
  if (sp == std::string::npos) return "";
  return action.substr(sp + 1, end - sp - 1);
}

}  // namespace

// ---- problems ---------------------------------------------------------------------

Problem dataset_problem(std::shared_ptr<const data::Dataset> ds, std::string name, const std::string& problem_id,
                        const data::PlanRecord* plan) {
  Problem s;
  s.dataset = std::move(name);
  s.problem = problem_id;
  s.pack = ds->pack_ptr();
  s.plan = plan;
  s.task = ds->task(problem_id);
  if (plan) {
    s.goals = ds->candidate_goals(*plan);
    s.true_goal = ds->true_goal_index(*plan);
    s.profiles = inference::plan_cost_profiles(*s.pack, *plan).profiles;
  } else {
    // No recorded plan: the pack's goal rule for the problem, its default profiles.
    data::PlanRecord only;
    only.id = only.problem_id = problem_id;
    s.goals = ds->candidate_goals(only);
    s.profiles = s.pack->default_profiles();
  }
  s.owner = std::move(ds);
  return s;
}

Problem dataset_problem(const std::string& dataset_dir, const std::string& problem_or_plan) {
  auto ds = std::make_shared<const data::Dataset>(data::Dataset::load(dataset_dir, false));
  const data::PlanRecord* plan = nullptr;
  for (const auto& p : ds->plans())
    if (p.id == problem_or_plan) plan = &p;
  if (plan) {
    Problem s = dataset_problem(ds, fs::path(dataset_dir).filename().string(), plan->problem_id, plan);
    s.true_goal = -1;  // a session on a plan id starts at the problem's initial state: nothing is known
    return s;
  }
  if (!fs::exists(ds->problem_path(problem_or_plan)))
    throw InputError("no problem or plan '" + problem_or_plan + "' in " + dataset_dir + " (no " +
                     ds->problem_path(problem_or_plan) + ")");
  return dataset_problem(ds, fs::path(dataset_dir).filename().string(), problem_or_plan, nullptr);
}

namespace {

std::vector<data::GoalSpec> chosen_goals(const GoalChoice& choice, const std::function<std::vector<data::GoalSpec>()>& rule) {
  std::vector<data::GoalSpec> out;
  if (!choice.conditions.empty()) {
    for (const auto& c : choice.conditions) out.push_back({c, c, "<goal>"});
    return out;
  }
  try {
    return rule();
  } catch (const InputError& e) {
    if (choice.hint.empty()) throw;
    throw InputError(std::string(e.what()) + "; " + choice.hint);
  }
}

}  // namespace

Problem domain_problem(const std::string& domain_dir, const std::string& problem_file, const GoalChoice& goals) {
  const fs::path dir(domain_dir), dom = dir / "domain.pddl";
  if (!fs::is_directory(dir)) throw InputError("domain folder '" + domain_dir + "' is not a directory");
  if (!fs::exists(dom)) throw InputError("domain folder '" + domain_dir + "' has no domain.pddl");
  if (!fs::exists(problem_file)) throw InputError("problem file '" + problem_file + "' does not exist");
  auto [domain, pack] = domains::load_domain_with_pack(dom.string(), domain_dir);
  Problem s;
  s.pack = pack;
  s.task = data::ground_problem(*pack, domain, problem_file);
  s.problem = fs::path(problem_file).stem().string();
  if (pack->spec().goals.source == domains::GoalSource::GoalSets && goals.conditions.empty()) {
    s.goals = data::folder_goal_set(domain_dir, s.problem);
  } else {
    // An init-capture: clang 14 (the fuzz build) cannot capture a structured binding.
    s.goals = chosen_goals(goals, [&, pk = pack] { return pk->problem_goals(*s.task, problem_file); });
  }
  s.profiles = pack->default_profiles();
  return s;
}

Problem text_problem(const std::string& domain_pddl, const std::string& problem_pddl, const std::string& pack_json,
                     const TextLabels& labels, int64_t max_ground_actions, const GoalChoice& goals) {
  auto domain = std::make_shared<const pddl::Domain>(pddl::parse_domain(domain_pddl, labels.domain));
  Problem s;
  s.pack = data::text_pack(*domain, pack_json, labels.pack);
  s.task = max_ground_actions > 0
               ? data::ground_problem_text(*s.pack, domain, problem_pddl, labels.problem, max_ground_actions)
               : data::ground_problem_text(*s.pack, domain, problem_pddl, labels.problem);
  s.problem = s.task->problem().name;
  s.goals = chosen_goals(goals, [&] { return data::text_problem_goals(*s.pack, *s.task, labels.problem); });
  s.profiles = s.pack->default_profiles();
  return s;
}

Problem generated_problem(const std::string& domain_dir, const domains::GenerateParams& params, uint64_t seed,
                          int attempts) {
  const fs::path dir(domain_dir), dom = dir / "domain.pddl";
  if (!fs::exists(dom)) throw InputError("domain folder '" + domain_dir + "' has no domain.pddl");
  auto [domain, pack] = domains::load_domain_with_pack(dom.string(), domain_dir);
  util::Rng rng(seed);
  for (int i = 0; i < attempts; ++i) {
    const auto drawn = pack->generate_problem(params, rng);
    if (!drawn) continue;
    Problem s;
    s.pack = pack;
    s.task = data::ground_problem_text(*pack, domain, drawn->pddl, "<generated problem>");
    s.problem = s.task->problem().name;
    s.goals = data::text_problem_goals(*pack, *s.task, "<generated problem>");
    s.profiles = pack->default_profiles();
    return s;
  }
  throw InputError("the " + pack->name() + " pack drew no problem with these counts in " + std::to_string(attempts) +
                   " attempts");
}

// ---- the engine ---------------------------------------------------------------------

struct Engine::Impl {
  Problem problem;
  SessionOptions options;
  std::shared_ptr<lm::LanguageModel> lm;
  inference::InferenceOptions io;
  std::vector<std::string> goal_labels, profile_names;
  domains::Roles roles;
  std::optional<pddl::Task::AtomRef> assistant_active;  // null: the domain has no turn predicate

  // What a call changes; a call works on a copy of the belief and commits it.
  std::shared_ptr<inference::Belief> belief;
  std::vector<inference::StepRecord> records;  // records[t]: after t actions
  std::vector<Event> events;
  struct Point {
    std::string label;
    std::array<std::vector<double>, 3> goals;  // per modality
  };
  std::vector<Point> history;
  std::optional<pddl::State> previous;
  // The latest instruction and the state it was heard in.
  std::optional<std::string> utterance;
  std::optional<pddl::State> utterance_state;
  std::vector<Step> steps;  // records in the engine's method
  mutable std::optional<language::ListenerResult> literal;  // the literal listener's reading, on demand
  // A replay of recorded observations updates the belief in place: the run
  // fails as a whole, so a copy per step would only cost time.
  bool in_place = false;

  Impl(Problem p, SessionOptions o, std::shared_ptr<lm::LanguageModel> model,
       const inference::InferenceOptions* inference = nullptr)
      : problem(std::move(p)), options(std::move(o)), lm(std::move(model)) {
    check_backend(options.language_model.backend);
    io = inference ? *inference : inference_options(options);
    if (!options.assist_rule.empty()) assist::parse_assist_rule(options.assist_rule);  // InputError names a bad value
    assist::parse_qa_floor(options.qa_floor);
    if (!options.goals.empty()) {
      problem.goals.clear();
      for (const auto& c : options.goals) problem.goals.push_back({c, c, "<goal>"});
      problem.true_goal = -1;
    }
    if (!options.cost_profiles.empty()) {
      problem.profiles.clear();
      for (const auto& n : options.cost_profiles) problem.profiles.push_back(problem.pack->cost_profile(n));
      model::link_alone_twins(problem.profiles);
    }
    if (problem.goals.empty()) throw InputError("problem '" + problem.problem + "' has no candidate goal");
    for (const auto& g : problem.goals) goal_labels.push_back(g.label);
    for (const auto& c : problem.profiles) profile_names.push_back(c.name);
    roles = problem.pack->roles();
    try {
      assistant_active = roles.turn_atom(*problem.task, roles.assistant);
    } catch (const InputError&) {
      assistant_active.reset();
    }
  }

  std::shared_ptr<inference::Belief> fresh_belief() const {
    return std::make_shared<inference::Belief>(problem.task, problem.pack, problem.goals, problem.profiles, io);
  }

  // Runs `work` on a copy of `from` (a fresh belief when null) under the
  // call's bounds; returns the copy when the call may commit it.
  template <typename F>
  std::shared_ptr<inference::Belief> bounded(const Bounds& b, const inference::Belief* from, F&& work) const {
    b.check();
    auto copy = !from ? fresh_belief() : in_place && from == belief.get() ? belief
                                                                          : std::make_shared<inference::Belief>(*from);
    copy->set_call_bounds(b.deadline(), b.stop_test());
    try {
      work(*copy);
    } catch (const inference::Interrupted&) {
      b.cancelled();
    } catch (...) {
      // Cancelled while it waited (e.g. on a language model server that then
      // failed): the caller asked for the call to stop, so that is the error.
      if (b.stop_requested()) b.cancelled();
      throw;
    }
    // A cancellation that came during the work (after the last refinement)
    // still drops it: the caller asked for the call not to happen.
    b.check();
    copy->set_call_bounds(Clock::time_point::max(), {});
    return copy;
  }

  Step to_step(const inference::StepRecord& r) const {
    Step s;
    s.t = r.t;
    s.action = r.action;
    if (!r.action.empty()) s.agent = agent_of(r.action);
    s.evidence = r.evidence;
    for (const auto& u : r.utterances) {
      s.utterances.push_back(u.text);
      if (!u.warning.empty()) s.utterance_warnings.push_back(u.warning);
    }
    s.posterior = convert(r[modality_of(options.method)]);
    s.seconds = r.seconds;
    return s;
  }

  Posterior convert(const inference::Posterior& p) const {
    return to_posterior(p, *belief, goal_labels, profile_names);
  }

  Point point(const std::string& label, const inference::Belief& b) const {
    Point p{label, {}};
    for (Modality m : inference::kModalities) p.goals[static_cast<int>(m)] = b.posterior(m).goals;
    return p;
  }

  void restep() {
    steps.clear();
    for (const auto& r : records) steps.push_back(to_step(r));
  }

  // The start at s_0 (a search: bounded like any call).
  // The start at s_0 with what was heard there, scored in its step (a
  // search: bounded like any call).
  void start(const Bounds& b, const std::vector<std::string>& heard = {}) {
    inference::StepRecord first;
    lm::LanguageModel* model = heard.empty() ? nullptr : &language_model();
    auto fresh = bounded(b, nullptr, [&](inference::Belief& x) { first = x.start(problem.task->initial_state(), heard, model); });
    belief = std::move(fresh);
    records = {std::move(first)};
    events.clear();
    for (const auto& u : heard) events.push_back({true, u, Event::Scored::AtStart});
    history = {point("start", *belief)};
    previous.reset();
    utterance.reset();
    utterance_state.reset();
    literal.reset();
    if (!heard.empty()) {
      utterance = heard.back();
      utterance_state = belief->state();
    }
    restep();
  }

  lm::LanguageModel& language_model() {
    if (!lm)
      lm = problem.owner ? dataset_language_model(options.language_model, problem.owner->dir(),
                                                  [this] { return problem.owner; })
                         : engine_language_model(options.language_model, *problem.pack, *problem.task, goal_labels);
    return *lm;
  }

  const Step& do_observe(pddl::ActionId a, const Bounds& b, const std::vector<std::string>& heard_before = {}) {
    inference::StepRecord r;
    const pddl::State before = belief->state();
    lm::LanguageModel* model = heard_before.empty() ? nullptr : &language_model();
    auto next = bounded(b, belief.get(), [&](inference::Belief& x) { r = x.observe(a, x.state(), heard_before, model); });
    belief = std::move(next);
    previous = before;
    const std::string name = problem.task->action_name(a);
    records.push_back(std::move(r));
    for (const auto& u : heard_before) events.push_back({true, u, Event::Scored::WithNextAction});
    if (!heard_before.empty()) {
      utterance = heard_before.back();
      utterance_state = before;
      literal.reset();
    }
    events.push_back({false, name});
    history.push_back(point(name, *belief));
    steps.push_back(to_step(records.back()));
    return steps.back();
  }

  const Step& do_hear(const std::vector<std::string>& texts, const Bounds& b) {
    lm::LanguageModel& model = language_model();
    inference::StepRecord r = records.back();
    auto next = bounded(b, belief.get(), [&](inference::Belief& x) { r = x.hear(texts, model, std::move(r)); });
    belief = std::move(next);
    records.back() = std::move(r);
    std::string label;
    for (const auto& text : texts) {
      events.push_back({true, text});
      label += (label.empty() ? "\"" : " \"") + text + "\"";
    }
    history.push_back(point(label, *belief));
    utterance = texts.back();
    utterance_state = belief->state();
    literal.reset();
    steps.back() = to_step(records.back());
    return steps.back();
  }

  bool assistant_turn() const {
    const pddl::State& s = belief->state();
    if (assistant_active) return problem.task->test(s, *assistant_active);
    for (pddl::ActionId a : problem.task->applicable_actions(s)) {
      const auto& args = problem.task->action(a).args;
      if (!args.empty() && problem.task->object_name(args[0]) == roles.assistant) return true;
    }
    return false;
  }

  const language::ListenerResult& literal_reading() {
    if (!literal) {
      auto setup = language::literal_listener_setup(problem.pack);
      literal = language::literal_listener(*problem.task, *utterance_state, *utterance, setup, language_model());
    }
    return *literal;
  }
};

Engine::Engine(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;
Engine::~Engine() = default;

Engine::Engine(Problem problem, SessionOptions options, std::shared_ptr<lm::LanguageModel> lm)
    : impl_(std::make_unique<Impl>(std::move(problem), std::move(options), std::move(lm))) {
  impl_->start(Bounds(CallLimits{}));
}

Engine::Engine(Problem problem, SessionOptions options, const inference::InferenceOptions& inference,
               std::shared_ptr<lm::LanguageModel> lm, const std::vector<std::string>& heard_at_start,
               const CallLimits& limits)
    : impl_(std::make_unique<Impl>(std::move(problem), std::move(options), std::move(lm), &inference)) {
  impl_->start(Bounds(limits), heard_at_start);
}

Engine Engine::replay(Problem problem, SessionOptions options, const inference::InferenceOptions& inference,
                      std::shared_ptr<lm::LanguageModel> lm, const pddl::PlanFile& observed) {
  const pddl::State s0 = problem.task->initial_state();
  const pddl::Simulation sim = pddl::simulate(*problem.task, s0, observed);  // InputError at the first bad step
  const int T = static_cast<int>(sim.actions.size());
  // heard[k]: the utterances annotated after k actions; one beyond T is never observed.
  std::vector<std::vector<std::string>> heard(T + 1);
  for (const auto& u : observed.utterances)
    if (u.index >= 0 && u.index <= T) heard[u.index].push_back(u.text);
  const bool before = inference.utterance_timing == inference::UtteranceTiming::Before;
  Engine e(std::move(problem), std::move(options), inference, std::move(lm), heard[0]);
  e.impl_->in_place = true;
  // "before": index k >= 1 is heard before a_k, in s_{k-1}. "after": index k
  // is heard in s_k, so 0 < k < T before a_{k+1} and k = T once the actions end.
  for (int t = 1; t <= T; ++t) {
    static const std::vector<std::string> none;
    const auto& with = before ? heard[t] : t >= 2 ? heard[t - 1] : none;
    e.impl_->do_observe(sim.actions[t - 1], Bounds(CallLimits{}), with);
  }
  if (!before && T >= 1 && !heard[T].empty()) e.impl_->do_hear(heard[T], Bounds(CallLimits{}));
  e.impl_->in_place = false;
  e.impl_->io.refine.deadline = Clock::time_point::max();  // a batch run's deadline is not the session's
  return e;
}

const Step& Engine::observe(const std::string& action, const CallLimits& limits) {
  const pddl::Task& task = *impl_->problem.task;
  const pddl::State& s = impl_->belief->state();
  // The label is cut: every token's location copies it, and a 200 kB action
  // string made that quadratic (issue 46).
  const pddl::PlanLine line{action, SourceLoc{"action " + pddl::printable(action, 80), 0, 0}};
  std::optional<pddl::ActionId> id;
  try {
    id = task.find_action(action);
  } catch (const InputError&) {
    id.reset();  // resolve_step below names what is wrong with the text
  }
  if (id && !task.applicable(*id, s.data())) {
    try {
      pddl::resolve_step(task, line, s);
    } catch (const InputError& e) {
      throw InapplicableActionError(action, e.what());
    }
    throw InapplicableActionError(action, action + " is not applicable in the current state");
  }
  if (!id) id = pddl::resolve_step(task, line, s);  // throws InputError naming the problem
  return impl_->do_observe(*id, Bounds(limits));
}

namespace {

// InputError for an id out of range, InapplicableActionError when its precondition is false in `s`.
void check_applicable(const pddl::Task& task, pddl::ActionId a, const pddl::State& s) {
  if (a < 0 || a >= task.num_actions())
    throw InputError("action id " + std::to_string(a) + " is out of range (0.." + std::to_string(task.num_actions() - 1) +
                     ")");
  if (!task.applicable(a, s.data())) {
    const auto& ga = task.action(a);
    throw InapplicableActionError(task.action_name(a), "action " + task.action_name(a) + " is not applicable: " +
                                                           task.explain_inapplicable(ga.schema, ga.args, s));
  }
}

}  // namespace

const Step& Engine::observe(pddl::ActionId a, const CallLimits& limits) {
  check_applicable(*impl_->problem.task, a, impl_->belief->state());
  return impl_->do_observe(a, Bounds(limits));
}

const Step& Engine::observe(pddl::ActionId a, const std::vector<std::string>& heard_before, const CallLimits& limits) {
  for (const auto& u : heard_before) data::check_utterance(u, SourceLoc{"utterance \"" + u + "\"", 0, 0});
  check_applicable(*impl_->problem.task, a, impl_->belief->state());
  return impl_->do_observe(a, Bounds(limits), heard_before);
}

const Step& Engine::hear(const std::string& utterance, const CallLimits& limits) {
  return hear(std::vector<std::string>{utterance}, limits);
}

const Step& Engine::hear(const std::vector<std::string>& utterances, const CallLimits& limits) {
  if (utterances.empty()) throw InputError("hear: no utterance given");
  for (const auto& u : utterances) data::check_utterance(u, SourceLoc{"utterance \"" + u + "\"", 0, 0});
  return impl_->do_hear(utterances, Bounds(limits));
}

const std::vector<inference::StepRecord>& Engine::records() const { return impl_->records; }
std::shared_ptr<const inference::Belief> Engine::belief() const { return impl_->belief; }

bool Engine::undo(const CallLimits& limits) {
  Impl& m = *impl_;
  // The principal's latest move or instruction: an instruction heard after
  // the last move goes alone, not with that move.
  int last = -1;
  for (int i = static_cast<int>(m.events.size()) - 1; i >= 0 && last < 0; --i) {
    if (m.events[i].utterance) {
      last = i;
      continue;
    }
    const auto a = m.problem.task->find_action(m.events[i].text);
    if (a && principal_action(*a)) last = i;
  }
  if (last < 0) return false;
  const std::vector<Event> keep(m.events.begin(), m.events.begin() + last);
  // Replayed on a new engine state, committed only when the whole replay is done.
  Impl replay(m.problem, m.options, m.lm, &m.io);
  const Bounds b(limits);
  std::vector<std::string> at_start, pending;
  for (const auto& e : keep)
    if (e.utterance && e.scored == Event::Scored::AtStart) at_start.push_back(e.text);
  replay.start(b, at_start);
  for (const auto& e : keep) {
    if (!e.utterance) {
      replay.do_observe(*m.problem.task->find_action(e.text), b, pending);
      pending.clear();
    } else if (e.scored == Event::Scored::WithNextAction) {
      pending.push_back(e.text);
    } else if (e.scored == Event::Scored::Heard) {
      replay.do_hear({e.text}, b);
    }
  }
  // Heard before the move taken back: heard in the state it was said in.
  if (!pending.empty()) replay.do_hear(pending, b);
  m.lm = replay.lm;
  m.belief = std::move(replay.belief);
  m.records = std::move(replay.records);
  m.events = std::move(replay.events);
  m.history = std::move(replay.history);
  m.previous = std::move(replay.previous);
  m.utterance = std::move(replay.utterance);
  m.utterance_state = std::move(replay.utterance_state);
  m.literal.reset();
  m.restep();
  return true;
}

void Engine::reset() { impl_->start(Bounds(CallLimits{})); }

void Engine::set_method(Method method) {
  impl_->options.method = method;
  impl_->restep();
}

AssistDecision Engine::assist(Method method, const CallLimits& limits) {
  Impl& m = *impl_;
  const Bounds b(limits);
  b.check();
  const pddl::Task& task = *m.problem.task;
  const Modality mod = modality_of(method);
  // Particle inference: the weighted hypotheses' policies must follow the
  // whole history (a copy is brought up to date and kept on success).
  std::shared_ptr<inference::Belief> belief = m.belief;
  if (belief->particle_mode()) belief = m.bounded(b, belief.get(), [&](inference::Belief& x) { x.sync_policies(mod); });
  const auto post = belief->posterior(mod);
  AssistDecision d;
  d.method = method_name(method);
  d.goals = m.goal_labels;
  d.goal_weights = post.goals;
  d.assistant_turn = m.assistant_turn();
  if (!d.assistant_turn) {
    m.belief = belief;
    return d;
  }
  const pddl::State& s = belief->state();
  const size_t nodes = m.options.assist_max_nodes > 0 ? m.options.assist_max_nodes : m.options.max_nodes;
  if (method == Method::Literal) {
    // The literal listener follows the most probable command for the latest
    // instruction: plan for its goal jointly, take the assistant's first step.
    pddl::ActionId chosen = m.roles.noop(task, m.roles.assistant);
    d.reason = "no instruction yet: wait";
    if (m.utterance) {
      const auto& ranked = m.literal_reading();
      if (!ranked.commands.empty()) {
        const auto& config = m.problem.pack->language();
        const auto& top = ranked.commands.front();
        search::SearchOptions so;
        so.max_nodes = nodes;
        so.max_seconds = m.options.search_seconds;
        so.deadline = b.deadline();
        const auto r = assist::command_plan(
            m.problem.task, top.command.to_goal_formula(config), m.problem.profiles[0], s, m.roles.principal,
            [&]() -> std::shared_ptr<heuristics::Heuristic> {
              return m.problem.pack->make_heuristic(m.problem.pack->spec().literal.planning_heuristic, task);
            },
            so);
        b.check();
        d.command = top.command.display_form();
        d.command_probability = top.prob;
        if (r.status == search::SearchStatus::Success && !r.plan.empty() && task.applicable(r.plan.front(), s.data())) {
          chosen = r.plan.front();
          d.reason = "first step of a plan for the most probable command";
        } else {
          d.reason = r.plan.empty() && r.status == search::SearchStatus::Success
                         ? "the command is already done: wait"
                         : "no plan for the command within the budget: wait";
        }
      }
    }
    d.id = chosen;
    d.action = task.action_name(chosen);
    m.belief = belief;
    return d;
  }
  assist::SetupOptions so;
  if (!m.options.assist_rule.empty()) so.rule = assist::parse_assist_rule(m.options.assist_rule);
  so.qa_floor = assist::parse_qa_floor(m.options.qa_floor);
  so.max_nodes = nodes;
  so.max_seconds = m.options.search_seconds;
  so.deadline = b.deadline();
  so.registered_options = registered_option_values(m.options);
  assist::AssistSetup setup = assist::setup_for(*m.problem.pack, m.problem.task, *belief, so);
  // The hypotheses with copies of their policies: deciding never changes the belief.
  std::vector<assist::Hypothesis> hyps = assistant_hypotheses(
      std::as_const(*belief), post, requests_for(task, m.records, post.hypotheses.size(), mod));
  // The decision's model timestep; past the horizon the floor counts one wait.
  const int t = std::min(belief->t() + 1, setup.horizon - 1);
  // Refined here, so that a cancellation is seen between the searches.
  assist::refine_live(setup, hyps, s, [&] { b.check_cancel(); });
  // The session's actions (records[0] is the start), for the round-of-waits rule.
  std::vector<pddl::ActionId> done;
  for (size_t i = 1; i < m.records.size(); ++i)
    if (const auto id = task.find_action(m.records[i].action)) done.push_back(*id);
  const bool stalled = assist::round_of_waits(setup, done);
  // The states since the last instruction, before s: what was asked and done
  // since is not asked again.
  std::vector<pddl::State> since;
  size_t heard = m.records.size();
  for (size_t i = 0; i < m.records.size(); ++i)
    if (!m.records[i].utterances.empty()) heard = i;
  if (heard < m.records.size()) {
    pddl::State x = task.initial_state();
    for (size_t i = 0; i < done.size() && i + 1 < m.records.size(); ++i) {
      if (i >= heard) since.push_back(x);
      if (!task.applicable(done[i], x.data())) break;
      x = task.apply(x, done[i]);
    }
  }
  const assist::Decision dec = engine::decide_of(m.options.assistance)({setup, hyps, s, t, stalled, &since});
  b.check();
  d.id = dec.action;
  d.action = task.action_name(dec.action);
  d.unanimous = dec.unanimous;
  d.broke_tie = dec.broke_tie;
  d.request_command = dec.request_command;
  d.followed_request = dec.followed_request;
  d.reason = dec.reason;
  for (size_t i = 0; i < dec.candidates.size(); ++i)
    d.candidates.push_back({dec.candidates[i], task.action_name(dec.candidates[i]), dec.values[i]});
  m.belief = belief;
  return d;
}

Method Engine::method() const { return impl_->options.method; }
const SessionOptions& Engine::options() const { return impl_->options; }
const Problem& Engine::problem() const { return impl_->problem; }
const pddl::Task& Engine::task() const { return *impl_->problem.task; }
const std::shared_ptr<const pddl::Task>& Engine::task_ptr() const { return impl_->problem.task; }
const domains::Pack& Engine::pack() const { return *impl_->problem.pack; }
const pddl::State& Engine::state() const { return impl_->belief->state(); }
const pddl::State* Engine::previous_state() const { return impl_->previous ? &*impl_->previous : nullptr; }
int Engine::t() const { return impl_->belief->t(); }

Posterior Engine::posterior(Method m) const { return impl_->convert(impl_->belief->posterior(modality_of(m))); }

const std::vector<Step>& Engine::trace() const { return impl_->steps; }

std::vector<HistoryPoint> Engine::history(Method m) const {
  std::vector<HistoryPoint> out;
  for (const auto& p : impl_->history) out.push_back({p.label, p.goals[static_cast<int>(modality_of(m))]});
  return out;
}

const std::vector<Engine::Event>& Engine::events() const { return impl_->events; }

bool Engine::assistant_turn() const { return impl_->assistant_turn(); }

std::string Engine::active_agent() const {
  return impl_->assistant_turn() ? impl_->roles.assistant : impl_->roles.principal;
}

bool Engine::principal_action(pddl::ActionId a) const {
  const auto& args = task().action(a).args;
  return !args.empty() && task().object_name(args[0]) == impl_->roles.principal;
}

std::vector<CandidateAction> Engine::applicable_actions() const {
  std::vector<CandidateAction> out;
  for (pddl::ActionId a : task().applicable_actions(state())) out.push_back({a, task().action_name(a), 0.0});
  return out;
}

bool Engine::goal_holds(int goal) const {
  if (goal < 0 || goal >= static_cast<int>(impl_->goal_labels.size()))
    throw InputError("goal index " + std::to_string(goal) + " is out of range (0.." +
                     std::to_string(impl_->goal_labels.size() - 1) + ")");
  for (const auto& h : impl_->belief->hypotheses())
    if (h.goal == goal) return h.spec->is_goal(state());
  return false;
}

bool Engine::goal_holds(const std::string& label) const {
  const auto& labels = impl_->goal_labels;
  for (size_t g = 0; g < labels.size(); ++g)
    if (labels[g] == label) return goal_holds(static_cast<int>(g));
  std::string known;
  for (const auto& l : labels) known += (known.empty() ? "" : ", ") + l;
  throw InputError("no candidate goal '" + clip_message(label, 200) + "' (goals: " + known + ")");
}

std::optional<int> Engine::reached_goal() const {
  for (const auto& h : impl_->belief->hypotheses())
    if (h.spec->is_goal(state())) return h.goal;
  return std::nullopt;
}

const std::vector<std::string>& Engine::goal_labels() const { return impl_->goal_labels; }
const std::vector<std::string>& Engine::profile_names() const { return impl_->profile_names; }

std::optional<Reading> Engine::reading(size_t top) const {
  Impl& m = *impl_;
  if (!m.utterance) return std::nullopt;
  Reading r;
  r.utterance = *m.utterance;
  // The record of the latest utterance.
  const inference::UtteranceRecord* rec = nullptr;
  for (auto it = m.records.rbegin(); it != m.records.rend() && !rec; ++it)
    if (!it->utterances.empty()) rec = &it->utterances.back();
  if (rec) {
    r.scored = true;
    r.evidence_weight = rec->evidence_weight;
    r.warning = rec->warning;
  }
  if (m.options.method == Method::Literal) {
    r.source = "literal listener (uniform prior over commands)";
    const auto& ranked = m.literal_reading();
    for (size_t i = 0; i < ranked.commands.size() && i < top; ++i)
      r.commands.push_back({ranked.commands[i].command.display_form(), ranked.commands[i].prob, {}});
  } else if (rec) {
    // P(command | u) = sum_h P(h | data) P(command | u, h): the commands each
    // goal would have the assistant do, weighted by the current posterior as
    // the assistant reads it (alone twins counted with their base profile,
    // whose commands are the ones the request rule follows).
    r.source = "speaker model, commands weighted by the goal posterior";
    const auto post =
        m.belief->posterior(m.options.method == Method::ActionOnly ? Modality::Both : modality_of(m.options.method));
    const std::vector<double> w = assistant_weights(*m.belief, post);
    std::map<std::string, double> mass;
    // A goal statement is its hypothesis' goal said in words: which goal, by
    // the mass each goal gave it (the page says the goal as the bars do).
    const std::string statement = "(make " + m.problem.pack->spec().language.speaker_pronoun + " ?goal1)";
    std::map<std::string, std::map<int, double>> stated;
    double empty = 0;
    const auto& hyps = m.belief->hypotheses();
    for (size_t h = 0; h < rec->hypotheses.size() && h < w.size(); ++h) {
      const auto& hu = rec->hypotheses[h];
      if (hu.commands.empty()) empty += w[h];
      for (const auto& c : hu.commands) {
        mass[c.command] += w[h] * c.posterior;
        if (h < hyps.size() && c.command.rfind(statement, 0) == 0) stated[c.command][hyps[h].goal] += w[h] * c.posterior;
      }
    }
    std::vector<std::pair<std::string, double>> ranked(mass.begin(), mass.end());
    if (empty > 0) ranked.emplace_back("(no command: the human needs no help)", empty);
    std::stable_sort(ranked.begin(), ranked.end(), [](auto& a, auto& b) { return a.second > b.second; });
    for (size_t i = 0; i < ranked.size() && i < top; ++i) {
      std::string goal;
      if (const auto it = stated.find(ranked[i].first); it != stated.end()) {
        const auto best = std::max_element(it->second.begin(), it->second.end(),
                                           [](auto& a, auto& b) { return a.second < b.second; });
        if (best->first >= 0 && best->first < static_cast<int>(m.goal_labels.size())) goal = m.goal_labels[best->first];
      }
      r.commands.push_back({ranked[i].first, ranked[i].second, std::move(goal)});
    }
  }
  return r;
}

size_t Engine::searches_stopped_by_budget() const { return impl_->belief->searches_stopped_by_budget(); }
size_t Engine::refinements() const { return impl_->belief->refinements(); }
int Engine::refine_threads() const { return impl_->belief->refine_threads(); }

}  // namespace clips::engine
