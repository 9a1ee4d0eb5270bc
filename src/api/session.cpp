// clips::Session (include/clips/session.hpp) over the internal stages: a
// Belief (inference/) for the posterior, assist::qmdp_decision / pibar_decision
// for the assistant's choice.
#include "clips/session.hpp"
#include "api/session_internals.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include "assist/assist.hpp"
#include "assist/request.hpp"
#include "assist/setup.hpp"
#include "clips/version.hpp"
#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "util/data_dir.hpp"

namespace clips {

namespace fs = std::filesystem;

namespace {

inference::Modality modality_of(Method m) {
  switch (m) {
    case Method::Clips: return inference::Modality::Both;
    case Method::LanguageOnly: return inference::Modality::UtteranceOnly;
    case Method::ActionOnly: return inference::Modality::ActionOnly;
  }
  throw InputError("unknown method");
}

// Language models are thread-safe and slow to build (the embedded one trains
// or loads its parameters), so sessions with the same settings share one.
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
  std::shared_ptr<lm::LanguageModel> m;
  try {
    m = language::make_language_model(o.backend, lo);
  } catch (const lm::LmError& e) {
    throw LanguageModelError(e.what());
  }
  models[key] = m;
  return m;
}

// The model a session hears with: for the embedded backend, the one `clips
// infer` and `clips serve` use on this domain (trained on the pack's corpora,
// else on a corpus generated from the domain, its problem and its goals);
// shared by sessions on the same domain, problem and goals.
std::shared_ptr<lm::LanguageModel> session_language_model(const LanguageModelOptions& o, const domains::Pack& pack,
                                                          const pddl::Task& task,
                                                          const std::vector<std::string>& goal_labels) {
  if (o.backend != "embedded") return shared_language_model(o);
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
  std::shared_ptr<lm::LanguageModel> m;
  try {
    m = language::make_domain_language_model(o.backend, {}, pack, task.domain(), {&task.problem()}, goal_labels);
  } catch (const lm::LmError& e) {
    throw LanguageModelError(e.what());
  }
  if (shared) models[key] = m;
  return m;
}

void check_backend(const std::string& backend) {
  for (const auto& k : language::language_model_kinds())
    if (k == backend) return;
  std::string known;
  for (const auto& k : language::language_model_kinds()) known += (known.empty() ? "" : ", ") + k;
  throw InputError("unknown language model backend '" + backend + "' (expected " + known + ")");
}

std::vector<data::GoalSpec> custom_goals(const std::vector<std::string>& conditions) {
  std::vector<data::GoalSpec> out;
  for (const auto& c : conditions) out.push_back({c, c, "<goal>"});
  return out;
}

std::vector<model::CostProfile> custom_profiles(const domains::Pack& pack, const std::vector<std::string>& names) {
  std::vector<model::CostProfile> out;
  for (const auto& n : names) out.push_back(pack.cost_profile(n));
  return out;
}

}  // namespace

struct Session::Impl {
  SessionOptions options;
  std::shared_ptr<const pddl::Task> task;
  domains::PackPtr pack;
  std::unique_ptr<inference::Belief> belief;
  std::shared_ptr<lm::LanguageModel> lm;  // built at the first utterance
  std::vector<std::string> goal_labels, profile_names;
  inference::StepRecord last;  // the belief's record of the current step
  std::vector<Step> trace;
  // What the last instruction asked for, per hypothesis (Q_MDP's request rule).
  std::vector<std::shared_ptr<const assist::Request>> requests;
  domains::Roles roles;
  std::optional<pddl::Task::AtomRef> assistant_active;  // null: the domain has no turn predicate (generic pack)

  Impl(SessionOptions o, std::shared_ptr<const pddl::Task> t, domains::PackPtr p, std::vector<data::GoalSpec> goals,
       std::vector<model::CostProfile> profiles)
      : options(std::move(o)), task(std::move(t)), pack(std::move(p)) {
    check_backend(options.language_model.backend);
    if (!options.goals.empty()) goals = custom_goals(options.goals);
    if (!options.cost_profiles.empty()) profiles = custom_profiles(*pack, options.cost_profiles);
    for (const auto& g : goals) goal_labels.push_back(g.label);
    for (const auto& p : profiles) profile_names.push_back(p.name);
    inference::InferenceOptions io;
    io.refine.max_nodes = options.max_nodes;
    io.threads = options.threads;
    io.assistant_turns = inference::parse_assistant_turns(options.assistant_turns);
    inference::apply_particle_settings({.particles = options.particles,
                                        .seed = options.particle_seed,
                                        .ess_threshold = options.ess_threshold,
                                        .moves = options.rejuvenation_moves,
                                        .rejuvenate = options.rejuvenate,
                                        .groups = options.proposal_groups,
                                        .filters = options.particle_filters,
                                        .estimate = options.particle_estimate},
                                       io);
    belief = std::make_unique<inference::Belief>(task, pack, std::move(goals), std::move(profiles), io);
    roles = pack->roles();
    try {
      assistant_active = roles.turn_atom(*task, roles.assistant);
    } catch (const InputError&) {
      assistant_active.reset();
    }
    last = belief->start(task->initial_state());
    trace.push_back(to_step(last));
  }

  Posterior convert(const inference::Posterior& p) const {
    Posterior out;
    out.goals = goal_labels;
    out.goal_probabilities = p.goals;
    out.cost_profiles = profile_names;
    out.cost_profile_probabilities = p.profiles;
    for (size_t h = 0; h < p.hypotheses.size(); ++h) {
      const auto& hy = belief->hypotheses()[h];
      out.hypotheses.push_back({goal_labels[hy.goal], profile_names[hy.profile], p.hypotheses[h]});
    }
    out.log_marginal_likelihood = p.log_marginal;
    return out;
  }

  Step to_step(const inference::StepRecord& r) const {
    Step s;
    s.t = r.t;
    s.action = r.action;
    if (!r.action.empty()) {
      // "(move human left)" -> "human": the acting agent is the first argument.
      const auto sp = r.action.find(' '), end = r.action.find_first_of(" )", sp + 1);
      if (sp != std::string::npos) s.agent = r.action.substr(sp + 1, end - sp - 1);
    }
    s.evidence = r.evidence;
    for (const auto& u : r.utterances) s.utterances.push_back(u.text);
    s.posterior = convert(r[modality_of(options.method)]);
    s.seconds = r.seconds;
    return s;
  }

  const Step& observe_id(pddl::ActionId a) {
    last = belief->observe(a, belief->state(), {}, nullptr);
    trace.push_back(to_step(last));
    return trace.back();
  }

  bool assistant_turn() const {
    const pddl::State& s = belief->state();
    if (assistant_active) return task->test(s, *assistant_active);
    for (pddl::ActionId a : task->applicable_actions(s)) {
      const auto& args = task->action(a).args;
      if (!args.empty() && task->object_name(args[0]) == roles.assistant) return true;
    }
    return false;
  }
};

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;
Session::~Session() = default;

Session Session::open_dataset(const std::string& dataset_dir, const std::string& problem, SessionOptions options) {
  data::Dataset ds = data::Dataset::load(dataset_dir, false);
  const data::PlanRecord* plan = nullptr;
  for (const auto& p : ds.plans())
    if (p.id == problem) plan = &p;
  std::vector<model::CostProfile> profiles;
  data::PlanRecord problem_only;
  if (plan) {
    profiles = inference::plan_cost_profiles(ds.pack(), *plan).profiles;
  } else {
    if (!fs::exists(ds.problem_path(problem)))
      throw InputError("no problem or plan '" + problem + "' in " + dataset_dir + " (no " + ds.problem_path(problem) + ")");
    problem_only.id = problem_only.problem_id = problem;
    plan = &problem_only;
    profiles = ds.pack().default_profiles();
  }
  auto task = ds.task(plan->problem_id);
  std::vector<data::GoalSpec> goals;
  if (options.goals.empty()) goals = ds.candidate_goals(*plan);
  return Session(std::make_unique<Impl>(std::move(options), task, ds.pack_ptr(), std::move(goals), std::move(profiles)));
}

Session Session::open_domain(const std::string& domain_dir, const std::string& problem_file, SessionOptions options) {
  const fs::path dir(domain_dir), dom = dir / "domain.pddl";
  if (!fs::is_directory(dir)) throw InputError("domain folder '" + domain_dir + "' is not a directory");
  if (!fs::exists(dom)) throw InputError("domain folder '" + domain_dir + "' has no domain.pddl");
  if (!fs::exists(problem_file)) throw InputError("problem file '" + problem_file + "' does not exist");
  auto [domain, pack] = domains::load_domain_with_pack(dom.string(), domain_dir);
  auto task = data::ground_problem(*pack, domain, problem_file);
  std::vector<data::GoalSpec> goals;
  if (options.goals.empty()) {
    if (pack->spec().goals.source == domains::GoalSource::GoalSets) {
      goals = data::folder_goal_set(domain_dir, fs::path(problem_file).stem().string());
    } else {
      try {
        goals = pack->problem_goals(*task, problem_file);
      } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + "; give the candidate goals in SessionOptions::goals");
      }
    }
  }
  auto profiles = pack->default_profiles();
  return Session(std::make_unique<Impl>(std::move(options), task, pack, std::move(goals), std::move(profiles)));
}

Session Session::open_domain_text(const std::string& domain_pddl, const std::string& problem_pddl,
                                  const std::string& pack_json, SessionOptions options) {
  auto domain = std::make_shared<pddl::Domain>(pddl::parse_domain(domain_pddl, "<domain text>"));
  domains::PackPtr pack = data::text_pack(*domain, pack_json, "<pack text>");
  auto task = data::ground_problem_text(*pack, domain, problem_pddl, "<problem text>");
  std::vector<data::GoalSpec> goals;
  if (options.goals.empty()) {
    try {
      goals = data::text_problem_goals(*pack, *task, "<problem text>");
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + "; give the candidate goals in SessionOptions::goals");
    }
  }
  auto profiles = pack->default_profiles();
  return Session(std::make_unique<Impl>(std::move(options), task, pack, std::move(goals), std::move(profiles)));
}

const Step& Session::observe(const std::string& action) {
  const pddl::Task& task = *impl_->task;
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
  return impl_->observe_id(*id);
}

const Step& Session::observe(int action_id) {
  const pddl::Task& task = *impl_->task;
  if (action_id < 0 || action_id >= task.num_actions())
    throw InputError("action id " + std::to_string(action_id) + " is out of range (0.." +
                     std::to_string(task.num_actions() - 1) + ")");
  const pddl::State& s = impl_->belief->state();
  if (!task.applicable(action_id, s.data())) {
    const auto& ga = task.action(action_id);
    throw InapplicableActionError(task.action_name(action_id), "action " + task.action_name(action_id) +
                                                                   " is not applicable: " +
                                                                   task.explain_inapplicable(ga.schema, ga.args, s));
  }
  return impl_->observe_id(action_id);
}

const Step& Session::hear(const std::string& utterance) {
  data::check_utterance(utterance, SourceLoc{"utterance \"" + utterance + "\"", 0, 0});
  Impl& m = *impl_;
  if (!m.lm) m.lm = session_language_model(m.options.language_model, *m.pack, *m.task, m.goal_labels);
  try {
    m.last = m.belief->hear({utterance}, *m.lm, m.last);
    if (!m.last.utterances.empty()) m.requests = assist::requests_from(*m.task, m.last.utterances.back());
  } catch (const lm::LmError& e) {
    throw LanguageModelError(e.what());
  }
  m.trace.back() = m.to_step(m.last);
  return m.trace.back();
}

Posterior Session::posterior() const { return posterior(impl_->options.method); }

Posterior Session::posterior(Method method) const {
  return impl_->convert(impl_->belief->posterior(modality_of(method)));
}

AssistDecision Session::assist() {
  Impl& m = *impl_;
  AssistDecision d;
  // Particle inference: the weighted hypotheses' policies follow the whole history.
  m.belief->sync_policies(modality_of(m.options.method));
  const auto post = m.belief->posterior(modality_of(m.options.method));
  d.goals = m.goal_labels;
  d.goal_weights = post.goals;
  d.assistant_turn = m.assistant_turn();
  if (!d.assistant_turn) return d;
  assist::AssistSetup setup = assist::setup_for(*m.pack, m.task, *m.belief);
  // The inference's own budget, so these refinements are the ones the next
  // observe() would make.
  setup.refine_options = search::SearchOptions{};
  setup.refine_options.max_nodes = m.options.max_nodes;
  std::vector<assist::Hypothesis> hyps;
  auto& policies = m.belief->policies();
  for (size_t h = 0; h < post.hypotheses.size(); ++h)
    hyps.push_back({post.hypotheses[h], std::shared_ptr<search::Policy>(&policies[h], [](search::Policy*) {}), nullptr});
  if (m.options.method != Method::ActionOnly) assist::attach_requests(hyps, m.requests);
  const int t = m.belief->t() + 1;  // the model timestep of the decision
  const assist::Decision dec = m.options.assistance == Assistance::QMdp
                                   ? assist::qmdp_decision(setup, hyps, setup.start, t)
                                   : assist::pibar_decision(setup, hyps, setup.start);
  d.id = dec.action;
  d.action = m.task->action_name(dec.action);
  d.unanimous = dec.unanimous;
  for (size_t i = 0; i < dec.candidates.size(); ++i)
    d.candidates.push_back({dec.candidates[i], m.task->action_name(dec.candidates[i]), dec.values[i]});
  return d;
}

int Session::t() const { return impl_->belief->t(); }

std::string Session::state() const {
  return impl_->pack->describe_state(*impl_->task, impl_->belief->state());
}

const std::vector<Step>& Session::trace() const { return impl_->trace; }

std::string Session::domain() const { return impl_->pack->name(); }

bool Session::assistant_turn() const { return impl_->assistant_turn(); }

std::string Session::active_agent() const { return assistant_turn() ? impl_->roles.assistant : impl_->roles.principal; }

std::vector<CandidateAction> Session::applicable_actions() const {
  std::vector<CandidateAction> out;
  for (pddl::ActionId a : impl_->task->applicable_actions(impl_->belief->state()))
    out.push_back({a, impl_->task->action_name(a), 0.0});
  return out;
}

std::string Session::action_name(int action_id) const {
  if (action_id < 0 || action_id >= impl_->task->num_actions())
    throw InputError("action id " + std::to_string(action_id) + " is out of range");
  return impl_->task->action_name(action_id);
}

std::string library_version() { return CLIPS_VERSION_STRING; }

std::string data_directory() { return util::data_dir(); }

const pddl::Task& SessionInternals::task(const Session& s) { return *s.impl_->task; }
const pddl::State& SessionInternals::state(const Session& s) { return s.impl_->belief->state(); }
const domains::Pack& SessionInternals::pack(const Session& s) { return *s.impl_->pack; }

}  // namespace clips
