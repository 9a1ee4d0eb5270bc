#include "serve/play_session.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/json.hpp"
#include "scenes/scenes.hpp"
#include "serve/messages.hpp"
#include "pddl/parser.hpp"
#include "util/error.hpp"

namespace clips::serve {

using engine::number_or_null;
using nlohmann::json;

std::vector<std::string> play_methods() { return method_names(); }

namespace {

// The method's canonical name (an older spelling is read too).
Method checked_method(const std::string& method) {
  try {
    return parse_method(method);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'method': ") + e.what());
  }
}

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
  const data::PlanRecord* plan = nullptr;
  for (const auto& p : ds->plans()) {
    if (p.problem_id != problem) continue;
    if (plan_id.empty() ? plan == nullptr : p.id == plan_id) plan = &p;
  }
  if (!plan && !plan_id.empty()) throw InputError("field 'plan': no plan '" + plan_id + "' on problem '" + problem + "'");
  try {
    ds->task(problem);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'problem': ") + e.what());
  }
  try {
    return engine::dataset_problem(std::move(ds), std::move(name), problem, plan);
  } catch (const InputError& e) {
    if (plan) throw;
    throw InputError("field 'problem': problem '" + problem + "' has no candidate goals: " + e.what());
  }
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
    // Said before the pack is read (which would look for the files). Only a
    // pack sent as text is limited so: without one, the server's own pack
    // for the domain (data/domains/<name>/, compiled in, or the generic one)
    // plays, and may read its own files.
    const auto j = nlohmann::json::parse(pack_json, nullptr, false);
    if (!no_pack && j.is_object() &&
        ((j.contains("fewshot") && j["fewshot"].is_object() && j["fewshot"].contains("file")) ||
         j.contains("embedded_corpus")))
      throw InputError("a pack sent as text may not name files (fewshot.file, embedded_corpus); leave them out");
    auto pack = data::text_pack(*domain, pack_json, "pack");
    if (!no_pack && (!pack->spec().fewshot.file.empty() || !pack->spec().embedded_corpus.empty()))
      throw InputError("a pack sent as text may not name files (fewshot.file, embedded_corpus); leave them out");
    return pack;
  });
  s.task = field("problem", [&] {
    data::GroundingLimits grounding(limits.text_max_ground_actions);
    grounding.deadline = std::chrono::steady_clock::now() +
                         std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(limits.text_ground_seconds));
    grounding.deadline_label = "field 'problem': grounding stopped at the server's limit of " +
                               std::to_string(static_cast<int>(limits.text_ground_seconds)) + " s";
    return data::ground_problem_text(*s.pack, domain, problem_pddl, "problem", grounding);
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

namespace {

// The engine of a session, after the server's own checks of the problem.
engine::Engine play_engine(PlaySetup setup, Method method, std::shared_ptr<lm::LanguageModel> lm,
                           const PlayLimits& limits) {
  if (setup.goals.empty()) throw InputError("field 'problem': problem '" + setup.problem + "' has no candidate goal");
  try {
    check_roles(*setup.task, *setup.pack);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'problem': ") + e.what());
  }
  if (limits.belief_threads < 0)
    throw InputError("belief_threads (--session-threads) must be >= 0 (0: all cores), got " +
                     std::to_string(limits.belief_threads));
  SessionOptions o = limits.belief;
  o.method = method;
  o.max_nodes = limits.inference_nodes;
  o.assist_max_nodes = limits.assist_nodes;
  o.search_seconds = limits.search_seconds;
  o.threads = limits.belief_threads;
  o.goals.clear();
  o.cost_profiles.clear();
  return engine::Engine(std::move(setup), std::move(o), std::move(lm));
}

}  // namespace

PlaySession::PlaySession(PlaySetup setup, const std::string& method, std::shared_ptr<lm::LanguageModel> lm,
                         PlayLimits limits)
    : dataset_name_(setup.dataset),
      problem_(setup.problem),
      plan_(setup.plan),
      true_goal_(setup.true_goal),
      player_goal_(setup.true_goal),
      goal_conditions_([&setup] {
        std::vector<std::string> c;
        for (const auto& g : setup.goals) c.push_back(g.condition);
        return c;
      }()),
      principal_(setup.pack->roles().principal),
      assistant_(setup.pack->roles().assistant),
      method_(method_name(checked_method(method))),
      limits_(limits),
      engine_(play_engine(std::move(setup), checked_method(method), std::move(lm), limits)),
      words_(engine_.task_ptr(), engine_.pack()) {
  switch (engine_.pack().spec().scene) {
    case domains::SceneKind::Grid: dkg_.emplace(engine_.task()); break;
    case domains::SceneKind::Cards: vh_.emplace(engine_.task()); break;
    case domains::SceneKind::Text: text_.emplace(engine_.task_ptr(), engine_.pack()); break;
  }
}

void PlaySession::act(const std::string& action) {
  const pddl::Task& task = engine_.task();
  const auto a = task.find_action(action);
  if (!a) throw InputError("field 'action': '" + action + "' is not an action of problem " + problem_);
  if (!task.applicable(*a, engine_.state().data()))
    throw ConflictError("action " + task.action_name(*a) + " is not applicable now (" + engine_.active_agent() +
                        "'s turn at step " + std::to_string(engine_.t()) + ")");
  if (engine_.t() >= limits_.max_steps)
    throw ConflictError("the session has reached its limit of " + std::to_string(limits_.max_steps) + " steps");
  engine_.observe(*a);
}

void PlaySession::hear(const std::string& utterance) {
  const bool blank = utterance.find_first_not_of(" \t\r\n") == std::string::npos;
  if (blank) throw InputError("field 'utterance': empty instruction");
  if (utterance.size() > limits_.max_utterance_bytes)
    throw InputError("field 'utterance': longer than " + std::to_string(limits_.max_utterance_bytes) + " bytes");
  if (utterance.find('\n') != std::string::npos) throw InputError("field 'utterance': must be one line");
  try {
    engine_.hear(utterance);
  } catch (const InputError& e) {
    throw InputError(std::string("field 'utterance': ") + e.what());
  }
}

json PlaySession::assist(bool apply) {
  const pddl::Task& task = engine_.task();
  if (!engine_.assistant_turn())
    throw ConflictError("it is the " + engine_.active_agent() + "'s turn, not the assistant's");
  if (apply && engine_.t() >= limits_.max_steps)
    throw ConflictError("the session has reached its limit of " + std::to_string(limits_.max_steps) + " steps");
  {
    bool any = false;
    for (pddl::ActionId a : task.applicable_actions(engine_.state())) {
      const auto& args = task.action(a).args;
      any |= !args.empty() && task.object_name(args[0]) == assistant_;
    }
    if (!any) throw ConflictError("the assistant (" + assistant_ + ") has no applicable action");
  }
  const AssistDecision dec = engine_.assist();
  json d = engine::to_json(dec);
  d["applied"] = apply;
  d["t"] = engine_.t();  // the step it was decided at
  if (apply) engine_.observe(static_cast<pddl::ActionId>(dec.id));
  decisions_.push_back({engine_.events().size(), apply, d});
  return d;
}

void PlaySession::undo() {
  if (!engine_.undo()) throw ConflictError("nothing to undo: no human action yet");
  // Decisions stay with the events they followed.
  std::erase_if(decisions_, [&](const Decided& d) { return d.events > engine_.events().size(); });
}

void PlaySession::reset() {
  decisions_.clear();
  engine_.reset();
}

// A method switch keeps the decisions: each names the method that made it.
void PlaySession::set_method(const std::string& method) {
  const Method m = checked_method(method);
  engine_.set_method(m);
  method_ = method_name(m);
}

json PlaySession::decision() const {
  const size_t events = engine_.events().size();
  for (auto it = decisions_.rbegin(); it != decisions_.rend(); ++it)
    if (it->applied ? it->events <= events : it->events == events) return it->decision;
  return nullptr;
}

json PlaySession::posterior() const {
  json j = engine::to_json(engine_.posterior(), engine_.method());
  // The colour each goal is drawn in (the page's bars and chart).
  for (auto& g : j["goals"]) g["colour"] = scenes::goal_colour(engine_.task(), engine_.pack(), g["goal"].get<std::string>());
  return j;
}

json PlaySession::trace() const {
  json steps = json::array();
  for (const auto& h : engine_.history()) steps.push_back({{"event", h.label}, {"goals", h.goals}});
  json events = json::array();
  for (const auto& e : engine_.events()) events.push_back({{"kind", e.utterance ? "utterance" : "action"}, {"text", e.text}});
  return {{"method", method_},
          {"modality", engine::evidence_name(engine_.method())},
          {"steps", std::move(steps)},
          {"events", std::move(events)}};
}

json PlaySession::scene() const {
  const pddl::State& s = engine_.state();
  if (text_) return text_->draw(s, engine_.previous_state(), engine_.active_agent());
  json j;
  if (dkg_) {
    const auto g = scenes::dkg_scene(*dkg_, s);
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
      // On the grid (1-based), carried, or neither: a key used up on a door.
      if (!o.held_by.empty()) oj["held_by"] = o.held_by;
      else if (o.x >= 1 && o.y >= 1) oj["x"] = o.x, oj["y"] = o.y;
      if (o.kind == render::ObjectKind::Door) oj["locked"] = o.locked;
      objs.push_back(std::move(oj));
    }
    j["objects"] = std::move(objs);
    j["active"] = g.active_agent;
  } else {
    const auto h = scenes::vh_scene(engine_.pack(), *vh_, s);
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
  const auto r = engine_.reading();
  if (!r) return nullptr;
  json j;
  j["utterance"] = r->utterance;
  // How much the instruction counted (1: fully; less when few of its words
  // are ones the model reads), with the reason, as `clips infer` warns.
  if (r->scored) {
    j["evidence_weight"] = r->evidence_weight;
    if (!r->warning.empty()) j["warning"] = r->warning;
  }
  if (!r->source.empty()) j["source"] = r->source;
  json cmds = json::array();
  // Each reading in parts (who does what to which objects), for the page to
  // say in words; a goal statement names its goal by label.
  for (const auto& c : r->commands) {
    json cj = {{"command", c.command}, {"p", c.p}, {"steps", words_.steps(c.command, !c.goal.empty())}};
    if (!c.goal.empty()) cj["goal"] = c.goal;
    cmds.push_back(std::move(cj));
  }
  j["commands"] = std::move(cmds);
  return j;
}

void PlaySession::set_player_goal(const std::optional<std::string>& label) {
  if (!label) {
    player_goal_ = -1;
    return;
  }
  const auto& labels = engine_.goal_labels();
  const auto it = std::find(labels.begin(), labels.end(), *label);
  if (it == labels.end()) {
    std::string known;
    for (const auto& l : labels) known += (known.empty() ? "" : ", ") + l;
    throw InputError("no candidate goal '" + echo(*label) + "' (goals: " + known + ")");
  }
  player_goal_ = static_cast<int>(it - labels.begin());
}

json PlaySession::state() const {
  const pddl::Task& task = engine_.task();
  const domains::Pack& pack = engine_.pack();
  json j;
  j["dataset"] = dataset_name_.empty() ? json(nullptr) : json(dataset_name_);
  j["domain"] = pack.name();
  j["problem"] = problem_;
  j["plan"] = plan_ ? json(plan_->id) : json(nullptr);
  j["method"] = method_;
  j["assistance"] = assistance_name(limits_.belief.assistance);
  j["t"] = engine_.t();
  const std::string turn = engine_.active_agent();
  j["turn"] = turn;
  j["principal"] = principal_;
  j["assistant"] = assistant_;
  // The principal's no-op ("(wait human)"), for a key that waits; null when the domain has none.
  const auto noop = task.find_action("(" + pack.roles().noop_action + " " + principal_ + ")");
  j["noop_action"] = noop ? json(task.action_name(*noop)) : json(nullptr);
  // The game ends at the player's goal only; other candidate goals may hold on the way.
  json holding = json::array();
  for (size_t g = 0; g < engine_.goal_labels().size(); ++g)
    if (engine_.goal_holds(static_cast<int>(g))) holding.push_back(engine_.goal_labels()[g]);
  const bool reached = player_goal_ >= 0 && engine_.goal_holds(player_goal_);
  j["reached_goal"] = reached ? json(engine_.goal_labels().at(player_goal_)) : json(nullptr);
  j["player_goal"] = player_goal_ >= 0 ? json(engine_.goal_labels().at(player_goal_)) : json(nullptr);
  j["goals_holding"] = std::move(holding);
  // Each candidate goal's condition, for the page to say the goal in words.
  json conditions = json::object();
  for (size_t g = 0; g < goal_conditions_.size() && g < engine_.goal_labels().size(); ++g)
    conditions[engine_.goal_labels()[g]] = goal_conditions_[g];
  j["goal_conditions"] = std::move(conditions);
  j["true_goal"] = true_goal_ >= 0 ? json(engine_.goal_labels().at(true_goal_)) : json(nullptr);
  j["scene"] = scene();
  json acts = json::array();
  if (turn == principal_)
    for (pddl::ActionId a : task.applicable_actions(engine_.state())) acts.push_back(task.action_name(a));
  j["actions"] = std::move(acts);
  j["posterior"] = posterior();
  json hist = json::array();
  for (const auto& h : engine_.history()) hist.push_back({{"event", h.label}, {"goals", h.goals}});
  j["history"] = std::move(hist);
  j["reading"] = reading();
  j["decision"] = decision();
  // The human moves of the reference plan (a hint for players and tests).
  json moves = json::array();
  j["observed_utterances"] = json::array();
  if (plan_) {
    for (const auto& a : plan_->observed.actions)
      if (const auto id = task.find_action(a.text); id && task.object_name(task.action(*id).args.at(0)) == principal_)
        moves.push_back(task.action_name(*id));
    for (const auto& u : plan_->observed.utterances) j["observed_utterances"].push_back(u.text);
  }
  j["observed_moves"] = std::move(moves);
  j["searches_stopped_by_budget"] = engine_.searches_stopped_by_budget();
  // Exact or particle inference, and the policy refinements done so far
  // (hypotheses × steps when exact; fewer where particles leave some out).
  j["inference"] = {{"particles", engine_.options().particles},
                    {"refinements", engine_.refinements()},
                    {"threads", engine_.refine_threads()}};
  return j;
}

}  // namespace clips::serve
