#include "serve/play_session.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "assist/assist.hpp"
#include "assist/request.hpp"
#include "assist/setup.hpp"
#include "eval/scenes.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "util/error.hpp"

namespace clips::serve {

using inference::Modality;
using nlohmann::json;

const std::vector<std::string>& play_methods() {
  static const std::vector<std::string> m = {"clips", "lang_only", "action_only", "literal"};
  return m;
}

namespace {

void check_method(const std::string& method) {
  const auto& m = play_methods();
  if (std::find(m.begin(), m.end(), method) == m.end())
    throw InputError("field 'method': unknown method '" + method + "' (known: clips, lang_only, action_only, literal)");
}

// JSON has no infinity: dead ends are sent as null.
json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string kind_name(render::ObjectKind k) {
  switch (k) {
    case render::ObjectKind::Human: return "human";
    case render::ObjectKind::Robot: return "robot";
    case render::ObjectKind::Key: return "key";
    case render::ObjectKind::Door: return "door";
    case render::ObjectKind::Gem: return "gem";
  }
  return "?";
}

}  // namespace

namespace {

// A problem id as the dataset lists it, never a path.
void check_problem_id(const data::Dataset& ds, const std::string& name, const std::string& problem) {
  const auto& ids = ds.problem_ids();
  if (std::find(ids.begin(), ids.end(), problem) == ids.end()) {
    std::string known;
    for (size_t i = 0; i < ids.size() && i < 12; ++i) known += (i ? ", " : "") + ids[i];
    if (ids.size() > 12) known += ", ...";
    throw InputError("field 'problem': dataset '" + name + "' has no problem '" + problem + "' (problems: " +
                     (known.empty() ? "none" : known) + ")");
  }
}

// The pack's principal and assistant are objects of the problem.
void check_roles(const pddl::Task& task, const domains::Pack& pack) {
  for (const auto& [agent, role] : {std::pair{pack.roles().principal, "principal"}, {pack.roles().assistant, "assistant"}})
    if (!task.find_object(agent))
      throw InputError("the problem has no object '" + agent + "' (the pack " + pack.name() + " names it as the " +
                       role + ")");
}

}  // namespace

PlaySetup dataset_setup(std::shared_ptr<const data::Dataset> ds, std::string name, const std::string& problem,
                        const std::string& plan_id) {
  check_problem_id(*ds, name, problem);
  PlaySetup s;
  s.dataset = std::move(name);
  s.problem = problem;
  s.pack = ds->pack_ptr();
  for (const auto& p : ds->plans()) {
    if (p.problem_id != problem) continue;
    if (plan_id.empty() ? s.plan == nullptr : p.id == plan_id) s.plan = &p;
  }
  if (!s.plan && !plan_id.empty())
    throw InputError("field 'plan': no plan '" + plan_id + "' on problem '" + problem + "'");
  try {
    s.task = ds->task(problem);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'problem': ") + e.what());
  }
  if (s.plan) {
    s.goals = ds->candidate_goals(*s.plan);
    s.true_goal = ds->true_goal_index(*s.plan);
    s.profiles = inference::plan_cost_profiles(*s.pack, *s.plan).profiles;
  } else {
    // No recorded plan: the pack's goal rule for the problem, its default profiles.
    data::PlanRecord only;
    only.id = only.problem_id = problem;
    try {
      s.goals = ds->candidate_goals(only);
    } catch (const InputError& e) {
      throw InputError("field 'problem': problem '" + problem + "' has no candidate goals: " + e.what());
    }
    s.profiles = s.pack->default_profiles();
  }
  s.owner = std::move(ds);
  return s;
}

PlaySetup text_setup(const std::string& domain_pddl, const std::string& problem_pddl, const std::string& pack_json,
                     const PlayLimits& limits) {
  auto field = [](const char* name, auto&& fn) {
    try {
      return fn();
    } catch (const InputError& e) {
      throw InputError(std::string("field '") + name + "': " + e.what());
    }
  };
  PlaySetup s;
  auto domain = field("domain", [&] { return std::make_shared<const pddl::Domain>(pddl::parse_domain(domain_pddl, "domain")); });
  const bool no_pack = pack_json.find_first_not_of(" \t\r\n") == std::string::npos;
  s.pack = field(no_pack ? "domain" : "pack", [&] {
    // Said before the pack is read (which would look for the files).
    const auto j = nlohmann::json::parse(pack_json, nullptr, false);
    if (j.is_object() && ((j.contains("fewshot") && j["fewshot"].is_object() && j["fewshot"].contains("file")) ||
                          j.contains("embedded_corpus")))
      throw InputError("a pack sent as text may not name files (fewshot.file, embedded_corpus); leave them out");
    auto pack = data::text_pack(*domain, pack_json, "pack");
    if (!pack->spec().fewshot.file.empty() || !pack->spec().embedded_corpus.empty())
      throw InputError("a pack sent as text may not name files (fewshot.file, embedded_corpus); leave them out");
    return pack;
  });
  s.task = field("problem", [&] {
    return data::ground_problem_text(*s.pack, domain, problem_pddl, "problem", limits.text_max_ground_actions);
  });
  s.problem = s.task->problem().name;
  field("problem", [&] {
    try {
      check_roles(*s.task, *s.pack);
    } catch (const InputError& e) {
      if (!no_pack) throw;
      throw InputError(std::string(e.what()) + "; no pack was sent, so the one found for domain '" + s.pack->name() +
                       "' plays (the generic pack when none is known): send the domain's pack as 'pack'");
    }
    return 0;
  });
  s.goals = field("problem", [&] { return data::text_problem_goals(*s.pack, *s.task, "problem"); });
  s.profiles = s.pack->default_profiles();
  return s;
}

PlaySession::PlaySession(PlaySetup setup, const std::string& method, std::shared_ptr<lm::LanguageModel> lm,
                         PlayLimits limits)
    : ds_(std::move(setup.owner)),
      dataset_name_(std::move(setup.dataset)),
      problem_(std::move(setup.problem)),
      plan_(setup.plan),
      task_(std::move(setup.task)),
      pack_(std::move(setup.pack)),
      goals_(std::move(setup.goals)),
      profiles_(std::move(setup.profiles)),
      true_goal_(setup.true_goal),
      method_(method),
      lm_(std::move(lm)),
      limits_(limits) {
  check_method(method_);
  if (goals_.empty()) throw InputError("field 'problem': problem '" + problem_ + "' has no candidate goal");
  principal_ = pack_->roles().principal;
  assistant_ = pack_->roles().assistant;
  horizon_ = pack_->roles().horizon;
  try {
    check_roles(*task_, *pack_);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'problem': ") + e.what());
  }
  switch (pack_->spec().scene) {
    case domains::SceneKind::Grid: dkg_.emplace(*task_); break;
    case domains::SceneKind::Cards: vh_.emplace(*task_); break;
    case domains::SceneKind::Text: text_.emplace(task_, *pack_); break;
  }
  options_ = limits_.belief;
  options_.refine.max_nodes = limits_.inference_nodes;
  options_.refine.max_seconds = limits_.search_seconds;
  if (limits_.belief_threads < 0) throw InputError("belief_threads (--session-threads) must be >= 0 (0: all cores), got " + std::to_string(limits_.belief_threads));
  options_.threads = limits_.belief_threads;
  rebuild({});
}

void PlaySession::rebuild(const std::vector<Event>& events) {
  belief_ = std::make_unique<inference::Belief>(task_, pack_, goals_, profiles_, options_);
  last_ = belief_->start(task_->initial_state());
  events_.clear();
  history_.clear();
  previous_.reset();
  // Decisions stay with the events they followed.
  std::erase_if(decisions_, [&](const Decided& d) { return d.events > events.size(); });
  utterance_.reset();
  utterance_state_.reset();
  utterance_record_.reset();
  literal_.reset();
  push_history("start");
  for (const auto& e : events) {
    if (e.utterance) apply_utterance(e.text);
    else apply_action(*task_->find_action(e.text));
  }
}

void PlaySession::push_history(const std::string& label) {
  HistoryPoint h;
  h.label = label;
  for (Modality m : inference::kModalities) h.goals[static_cast<int>(m)] = last_[m].goals;
  history_.push_back(std::move(h));
}

void PlaySession::apply_action(pddl::ActionId a) {
  previous_ = belief_->state();
  last_ = belief_->observe(a);
  events_.push_back({false, task_->action_name(a)});
  push_history(task_->action_name(a));
}

void PlaySession::apply_utterance(const std::string& text) {
  last_ = belief_->hear({text}, *lm_, std::move(last_));
  events_.push_back({true, text});
  utterance_ = text;
  utterance_state_ = belief_->state();
  utterance_record_ = last_.utterances.empty() ? std::nullopt : std::optional(last_.utterances.back());
  literal_.reset();
  push_history("\"" + text + "\"");
}

void PlaySession::act(const std::string& action) {
  const auto a = task_->find_action(action);
  if (!a) throw InputError("field 'action': '" + action + "' is not an action of problem " + problem_);
  if (!task_->applicable(*a, belief_->state().data()))
    throw ConflictError("action " + task_->action_name(*a) + " is not applicable now (" + active_agent() +
                        "'s turn at step " + std::to_string(belief_->t()) + ")");
  if (belief_->t() >= limits_.max_steps)
    throw ConflictError("the session has reached its limit of " + std::to_string(limits_.max_steps) + " steps");
  apply_action(*a);
}

void PlaySession::hear(const std::string& utterance) {
  const bool blank = utterance.find_first_not_of(" \t\r\n") == std::string::npos;
  if (blank) throw InputError("field 'utterance': empty instruction");
  if (utterance.size() > limits_.max_utterance_bytes)
    throw InputError("field 'utterance': longer than " + std::to_string(limits_.max_utterance_bytes) + " bytes");
  if (utterance.find('\n') != std::string::npos) throw InputError("field 'utterance': must be one line");
  apply_utterance(utterance);
}

Modality PlaySession::modality() const {
  if (method_ == "lang_only") return Modality::UtteranceOnly;
  if (method_ == "action_only") return Modality::ActionOnly;
  return Modality::Both;  // clips; literal shows the CLIPS belief beside its own reading
}

std::string PlaySession::active_agent() const { return pack_->roles().active_agent(*task_, belief_->state()); }

std::optional<std::string> PlaySession::reached_goal() const {
  for (const auto& h : belief_->hypotheses())
    if (h.spec->is_goal(belief_->state())) return goals_[h.goal].label;
  return std::nullopt;
}

const language::ListenerResult& PlaySession::literal_reading() const {
  if (!literal_) {
    auto setup = language::literal_listener_setup(pack_);
    literal_ = language::literal_listener(*task_, *utterance_state_, *utterance_, setup, *lm_);
  }
  return *literal_;
}

json PlaySession::assist(bool apply) {
  const pddl::State& s = belief_->state();
  if (active_agent() != assistant_)
    throw ConflictError("it is the " + active_agent() + "'s turn, not the assistant's");
  if (apply && belief_->t() >= limits_.max_steps)
    throw ConflictError("the session has reached its limit of " + std::to_string(limits_.max_steps) + " steps");
  {
    bool any = false;
    for (pddl::ActionId a : task_->applicable_actions(s)) {
      const auto& args = task_->action(a).args;
      any |= !args.empty() && task_->object_name(args[0]) == assistant_;
    }
    if (!any) throw ConflictError("the assistant (" + assistant_ + ") has no applicable action");
  }
  json d;
  d["method"] = method_;
  pddl::ActionId chosen = -1;
  const int t = std::min(belief_->t() + 1, horizon_ - 1);
  if (method_ == "literal") {
    // The literal listener follows the most probable command for the latest
    // instruction: plan for its goal jointly, take the assistant's first step.
    chosen = pack_->roles().noop(*task_, assistant_);
    d["reason"] = "no instruction yet: wait";
    if (utterance_) {
      const auto& ranked = literal_reading();
      if (!ranked.commands.empty()) {
        const auto& config = pack_->language();
        const auto& top = ranked.commands.front();
        auto spec = std::make_shared<model::Specification>(task_, top.command.to_goal_formula(config), profiles_[0]);
        std::unique_ptr<heuristics::Heuristic> h = pack_->make_heuristic(pack_->spec().literal.planning_heuristic, *task_);
        search::SearchOptions so;
        so.max_nodes = limits_.assist_nodes;
        so.max_seconds = limits_.search_seconds;
        auto r = search::plan(*spec, *h, s, so);
        d["command"] = top.command.display_form();
        d["command_probability"] = top.prob;
        if (r.status == search::SearchStatus::Success && !r.plan.empty() &&
            task_->applicable(r.plan.front(), s.data())) {
          chosen = r.plan.front();
          d["reason"] = "first step of a plan for the most probable command";
        } else {
          d["reason"] = r.plan.empty() && r.status == search::SearchStatus::Success
                            ? "the command is already done: wait"
                            : "no plan for the command within the budget: wait";
        }
      }
    }
    d["candidates"] = json::array();
  } else {
    assist::AssistSetup setup = assist::setup_for(*pack_, task_, *belief_);
    setup.start = s;
    setup.refine_options.max_nodes = limits_.assist_nodes;
    setup.refine_options.max_seconds = limits_.search_seconds;
    belief_->sync_policies(modality());  // particle inference: the weighted policies up to date
    const auto post = belief_->posterior(modality());
    std::vector<assist::Hypothesis> hyps;
    for (size_t h = 0; h < post.hypotheses.size(); ++h)
      hyps.push_back({post.hypotheses[h], std::make_shared<search::Policy>(belief_->policies()[h]), nullptr});
    if (modality() != inference::Modality::ActionOnly && utterance_record_)
      assist::attach_requests(hyps, assist::requests_from(*task_, *utterance_record_));
    auto q = assist::qmdp_decision(setup, hyps, s, t);
    chosen = q.action;
    d["unanimous"] = q.unanimous;
    d["reason"] = q.broke_tie ? "tied at the best value; this one carries out the request \"" + q.request_command + "\""
                  : q.unanimous ? "every likely goal agrees" : "highest expected value over the goal posterior";
    json cands = json::array();
    for (size_t i = 0; i < q.candidates.size(); ++i)
      cands.push_back({{"action", task_->action_name(q.candidates[i])}, {"value", number_or_null(q.values[i])}});
    d["candidates"] = std::move(cands);
  }
  d["action"] = task_->action_name(chosen);
  d["applied"] = apply;
  d["t"] = belief_->t();  // the step it was decided at
  if (apply) apply_action(chosen);
  decisions_.push_back({events_.size(), apply, d});
  return d;
}

void PlaySession::undo() {
  int last_human = -1;
  for (int i = static_cast<int>(events_.size()) - 1; i >= 0 && last_human < 0; --i) {
    if (events_[i].utterance) continue;
    const auto a = task_->find_action(events_[i].text);
    const auto& ga = task_->action(*a);
    if (!ga.args.empty() && task_->object_name(ga.args[0]) == principal_) last_human = i;
  }
  if (last_human < 0) throw ConflictError("nothing to undo: no human action yet");
  std::vector<Event> keep(events_.begin(), events_.begin() + last_human);
  rebuild(keep);
}

void PlaySession::reset() {
  decisions_.clear();
  rebuild({});
}

// A method switch keeps the decisions: each names the method that made it.
void PlaySession::set_method(const std::string& method) {
  check_method(method);
  method_ = method;
}

json PlaySession::decision() const {
  for (auto it = decisions_.rbegin(); it != decisions_.rend(); ++it)
    if (it->applied ? it->events <= events_.size() : it->events == events_.size()) return it->decision;
  return nullptr;
}

json PlaySession::posterior_json(Modality m) const {
  const auto post = belief_->posterior(m);
  json j;
  j["modality"] = inference::to_string(m);
  json goals = json::array();
  for (size_t g = 0; g < goals_.size(); ++g)
    goals.push_back({{"goal", goals_[g].label},
                     {"colour", eval::goal_colour(*task_, *pack_, goals_[g].label)},
                     {"p", post.goals[g]}});
  j["goals"] = std::move(goals);
  json profiles = json::array();
  for (size_t c = 0; c < profiles_.size(); ++c) profiles.push_back({{"profile", profiles_[c].name}, {"p", post.profiles[c]}});
  j["profiles"] = std::move(profiles);
  json hyps = json::array();
  for (size_t h = 0; h < belief_->hypotheses().size(); ++h) {
    const auto& hy = belief_->hypotheses()[h];
    hyps.push_back({{"goal", goals_[hy.goal].label}, {"profile", profiles_[hy.profile].name}, {"p", post.hypotheses[h]}});
  }
  j["hypotheses"] = std::move(hyps);
  j["log_marginal"] = number_or_null(post.log_marginal);
  return j;
}

json PlaySession::posterior() const { return posterior_json(modality()); }

json PlaySession::trace() const {
  json steps = json::array();
  const int m = static_cast<int>(modality());
  for (const auto& h : history_) steps.push_back({{"event", h.label}, {"goals", h.goals[m]}});
  json events = json::array();
  for (const auto& e : events_) events.push_back({{"kind", e.utterance ? "utterance" : "action"}, {"text", e.text}});
  return {{"modality", inference::to_string(modality())}, {"steps", std::move(steps)}, {"events", std::move(events)}};
}

json PlaySession::scene() const {
  const pddl::State& s = belief_->state();
  if (text_) return text_->draw(s, previous_ ? &*previous_ : nullptr, active_agent());
  json j;
  if (dkg_) {
    const auto g = eval::dkg_scene(*dkg_, s);
    j["kind"] = "grid";
    j["width"] = g.width;
    j["height"] = g.height;
    // One string per row, '#' for a wall: compact and easy to draw.
    json rows = json::array();
    for (int y = 1; y <= g.height; ++y) {
      std::string row;
      for (int x = 1; x <= g.width; ++x) row += g.wall(x, y) ? '#' : '.';
      rows.push_back(row);
    }
    j["walls"] = std::move(rows);
    json objs = json::array();
    for (const auto& o : g.objects) {
      json oj = {{"name", o.name}, {"kind", kind_name(o.kind)}, {"colour", o.colour}};
      if (o.held_by.empty()) oj["x"] = o.x, oj["y"] = o.y;
      else oj["held_by"] = o.held_by;
      if (o.kind == render::ObjectKind::Door) oj["locked"] = o.locked;
      objs.push_back(std::move(oj));
    }
    j["objects"] = std::move(objs);
    j["active"] = g.active_agent;
  } else {
    const auto h = eval::vh_scene(*pack_, *vh_, s);
    j["kind"] = "home";
    json fixtures = json::array();
    for (const auto& f : h.fixtures) fixtures.push_back({{"name", f.name}, {"piles", f.piles}});
    j["fixtures"] = std::move(fixtures);
    json agents = json::array();
    for (const auto& a : h.agents)
      agents.push_back({{"name", a.name}, {"kind", kind_name(a.kind)}, {"at", a.at}, {"held", a.held}});
    j["agents"] = std::move(agents);
    j["active"] = h.active_agent;
  }
  return j;
}

json PlaySession::reading() const {
  if (!utterance_) return nullptr;
  json j;
  j["utterance"] = *utterance_;
  // How much the instruction counted (1: fully; less when few of its words
  // are ones the model reads), with the reason, as `clips infer` warns.
  if (utterance_record_) {
    j["evidence_weight"] = utterance_record_->evidence_weight;
    if (!utterance_record_->warning.empty()) j["warning"] = utterance_record_->warning;
  }
  json cmds = json::array();
  if (method_ == "literal") {
    j["source"] = "literal listener (uniform prior over commands)";
    const auto& r = literal_reading();
    for (size_t i = 0; i < r.commands.size() && i < 5; ++i)
      cmds.push_back({{"command", r.commands[i].command.display_form()}, {"p", r.commands[i].prob}});
  } else if (utterance_record_) {
    // P(command | u) = Σ_h P(h | data) P(command | u, h): the commands each
    // goal would have the assistant do, weighted by the current posterior.
    j["source"] = "speaker model, commands weighted by the goal posterior";
    const auto post = belief_->posterior(method_ == "action_only" ? Modality::Both : modality());
    std::map<std::string, double> mass;
    double empty = 0;
    for (size_t h = 0; h < utterance_record_->hypotheses.size() && h < post.hypotheses.size(); ++h) {
      const auto& hu = utterance_record_->hypotheses[h];
      if (hu.commands.empty()) empty += post.hypotheses[h];
      for (const auto& c : hu.commands) mass[c.command] += post.hypotheses[h] * c.posterior;
    }
    std::vector<std::pair<std::string, double>> ranked(mass.begin(), mass.end());
    if (empty > 0) ranked.emplace_back("(no command: the human needs no help)", empty);
    std::stable_sort(ranked.begin(), ranked.end(), [](auto& a, auto& b) { return a.second > b.second; });
    for (size_t i = 0; i < ranked.size() && i < 5; ++i) cmds.push_back({{"command", ranked[i].first}, {"p", ranked[i].second}});
  }
  j["commands"] = std::move(cmds);
  return j;
}

json PlaySession::state() const {
  json j;
  j["dataset"] = dataset_name_.empty() ? json(nullptr) : json(dataset_name_);
  j["domain"] = pack_->name();
  j["problem"] = problem_;
  j["plan"] = plan_ ? json(plan_->id) : json(nullptr);
  j["method"] = method_;
  j["t"] = belief_->t();
  j["turn"] = active_agent();
  j["principal"] = principal_;
  j["assistant"] = assistant_;
  // The principal's no-op ("(wait human)"), for a key that waits; null when the domain has none.
  const auto noop = task_->find_action("(" + pack_->roles().noop_action + " " + principal_ + ")");
  j["noop_action"] = noop ? json(task_->action_name(*noop)) : json(nullptr);
  const auto reached = reached_goal();
  j["reached_goal"] = reached ? json(*reached) : json(nullptr);
  j["true_goal"] = true_goal_ >= 0 ? json(goals_.at(true_goal_).label) : json(nullptr);
  j["scene"] = scene();
  json acts = json::array();
  if (active_agent() == principal_)
    for (pddl::ActionId a : task_->applicable_actions(belief_->state())) acts.push_back(task_->action_name(a));
  j["actions"] = std::move(acts);
  j["posterior"] = posterior();
  json hist = json::array();
  const int m = static_cast<int>(modality());
  for (const auto& h : history_) hist.push_back({{"event", h.label}, {"goals", h.goals[m]}});
  j["history"] = std::move(hist);
  j["reading"] = reading();
  j["decision"] = decision();
  // The human moves of the reference plan (a hint for players and tests).
  json moves = json::array();
  j["observed_utterances"] = json::array();
  if (plan_) {
    for (const auto& a : plan_->observed.actions)
      if (const auto id = task_->find_action(a.text); id && task_->object_name(task_->action(*id).args.at(0)) == principal_)
        moves.push_back(task_->action_name(*id));
    for (const auto& u : plan_->observed.utterances) j["observed_utterances"].push_back(u.text);
  }
  j["observed_moves"] = std::move(moves);
  j["searches_stopped_by_budget"] = belief_->searches_stopped_by_budget();
  // Exact or particle inference, and the policy refinements done so far
  // (hypotheses × steps when exact; fewer where particles leave some out).
  j["inference"] = {{"particles", options_.particles},
                    {"refinements", belief_->refinements()},
                    {"threads", belief_->refine_threads()}};
  return j;
}

}  // namespace clips::serve
