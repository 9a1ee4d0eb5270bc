#include "inference/belief.hpp"

#include "language/deixis.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <optional>

#include "heuristics/basic.hpp"
#include "heuristics/conditions.hpp"
#include "lm/readability.hpp"
#include "pddl/plan.hpp"
#include "search/astar.hpp"
#include "util/error.hpp"

namespace clips::inference {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

util::Choices<Modality>& modality_choices() {
  static util::Choices<Modality> table(
      "modality", {{Modality::Both, "both", "actions and utterances", {}},
                   {Modality::UtteranceOnly, "utterance", "utterances only", {"language"}},
                   {Modality::ActionOnly, "action", "actions only", {}}});
  return table;
}
std::string to_string(Modality m) { return modality_choices().name(m); }
Modality parse_modality(const std::string& text) { return modality_choices().parse(text); }

util::Choices<AssistantTurns>& assistant_turns_choices() {
  static util::Choices<AssistantTurns> table(
      "assistant-turn refinement",
      {{AssistantTurns::Taken, "taken", "one lookahead, from the state its action led to; with an utterance there or after the last action, "
        "hypotheses whose plan from the state is stored are not searched further, since that plan explains it", {}},
       {AssistantTurns::All, "all", "the paper's REFINE, from every successor", {}}});
  return table;
}
std::string to_string(AssistantTurns a) { return assistant_turns_choices().name(a); }
AssistantTurns parse_assistant_turns(const std::string& text) { return assistant_turns_choices().parse(text); }

ProfileSet plan_cost_profiles(const domains::Pack& pack, const data::PlanRecord& plan) {
  pack.check_plan_tag(plan.tag, plan.id);
  return pack.profiles_for(plan.tag);
}

// ---------------------------------------------------------------------------

Belief::Belief(std::shared_ptr<const pddl::Task> task, domains::PackPtr pack, std::vector<data::GoalSpec> goals,
               std::vector<model::CostProfile> profiles, InferenceOptions options)
    : task_(std::move(task)),
      pack_(std::move(pack)),
      goals_(std::move(goals)),
      profiles_(std::move(profiles)),
      options_(std::move(options)) {
  if (goals_.empty() || profiles_.empty()) throw InputError("inference needs at least one goal and one cost profile");
  if (!pack_) throw InputError("inference needs a domain pack");
  check_options(options_);
  const domains::InferenceSettings& settings = pack_->spec().inference;
  search_ = options_.search.value_or(settings.search);
  noise_ = options_.utterance_noise.value_or(settings.utterance_noise);
  if (!(noise_ >= 0 && noise_ < 1)) throw InputError("utterance noise must be in [0, 1), not " + std::to_string(noise_));
  exponent_ = options_.utterance_exponent.value_or(settings.utterance_exponent);
  if (!(exponent_ > 0 && exponent_ <= 10))
    throw InputError("utterance exponent must be above 0 and at most 10, not " + std::to_string(exponent_));
  const std::string hname = options_.heuristic.empty() ? settings.heuristic : options_.heuristic;
  const TemperatureWeights prior = options_.temperature_prior.value_or(
      inverse_gamma_prior(settings.temperature_shape, settings.temperature_scale));
  utterance_model_ = std::make_shared<UtteranceModel>(task_, pack_, options_.utterance);
  const pddl::State s0 = task_->initial_state();
  // One state graph for all hypotheses: they search the same neighbourhood.
  if (search_) graph_ = std::make_shared<search::StateGraph>(task_);
  for (int g = 0; g < static_cast<int>(goals_.size()); ++g)
    for (int c = 0; c < static_cast<int>(profiles_.size()); ++c) {
      auto spec = std::make_shared<model::Specification>(task_, goals_[g].condition, profiles_[c],
                                                         goals_[g].source.empty() ? "<goal>" : goals_[g].source);
      // One heuristic per hypothesis: prepare() binds it to its specification.
      std::shared_ptr<heuristics::Heuristic> h = pack_->make_heuristic(hname, *task_);
      // Without search, V = -h is read directly, so bind h to the goal now.
      if (!search_) h->prepare(*spec, s0);
      hyps_.push_back({g, c, spec});
      policies_.emplace_back(spec, std::move(h), graph_);
      temps_.emplace_back(prior);
    }
  for (const Hypothesis& h : hyps_) {
    const int base = profiles_[static_cast<size_t>(h.profile)].twin_of;
    // Hypotheses are enumerated goal-major: (g, c) at g * |profiles| + c.
    base_of_.push_back(h.goal * static_cast<int>(profiles_.size()) + (base >= 0 ? base : h.profile));
  }
  // A delegating speaker per hypothesis that speaks for itself (twins speak
  // as their base): the assistant's actions cost just above its no-op.
  const double delegates = settings.speaker_delegates;
  if (search_ && delegates > 0 && utterance_model_->plans_rule() == domains::RolloutSettings::Plans::Tied) {
    delegate_share_ = delegates;
    const domains::Roles& roles = pack_->spec().roles;
    const double factor = std::min(1.0, roles.noop_cost + 0.1);
    delegate_of_.assign(hyps_.size(), -1);
    for (size_t h = 0; h < hyps_.size(); ++h) {
      if (base_of_[h] != static_cast<int>(h)) continue;
      const model::CostProfile& base = profiles_[static_cast<size_t>(hyps_[h].profile)];
      auto spec = std::make_shared<model::Specification>(
          task_, hyps_[h].spec->goal_text(),
          model::scaled_assistant(base, base.name + "-delegating", roles.assistant, roles.noop_action, factor));
      delegate_of_[h] = static_cast<int>(delegates_.size());
      delegates_.emplace_back(spec, pack_->make_heuristic(hname, *task_), graph_);
    }
  }
  heuristic_name_ = hname;
  if (search_ && settings.request_plans > 0) request_share_ = settings.request_plans;
  if (search_ && settings.sparing_plans > 0) spare_share_ = settings.sparing_plans;
  progress_share_ = settings.progress_share;
  const double n = static_cast<double>(hyps_.size());
  log_prior_.assign(hyps_.size(), -std::log(n));
  action_ll_.assign(hyps_.size(), 0.0);
  utterance_ll_.assign(hyps_.size(), 0.0);
  if (auto sp = task_->find_object(utterance_model_->config().speaker)) speaker_ = *sp;
  state_ = s0;
  if (search_ && options_.threads != 1 && hyps_.size() > 1) {
    auto pool = std::make_shared<util::WorkerPool>(options_.threads);
    if (pool->threads() > 1) pool_ = std::move(pool);
  }
  if (options_.particles > 0) {
    cursor_.assign(hyps_.size(), 0);
    for (Modality m : kModalities) {
      ParticleOptions po;
      po.particles = options_.particles;
      po.ess_threshold = options_.ess_threshold;
      po.rejuvenation_moves = options_.rejuvenation_moves;
      po.rejuvenate_on_evidence = options_.rejuvenate != Rejuvenation::Resampling;
      po.proposal_groups = options_.proposal_groups;
      po.estimate = options_.particle_estimate;
      // One stream per modality: a filter's draws do not depend on the others'.
      po.seed = util::Rng::derive(options_.particle_seed, {static_cast<uint64_t>(m)});
      filters_.emplace_back(static_cast<int>(goals_.size()), static_cast<int>(profiles_.size()), po);
    }
  }
}

void check_options(const InferenceOptions& o) {
  if (o.particles < 0) throw InputError(fmt::format("particles must be 0 (exact) or positive, not {}", o.particles));
  if (!(o.ess_threshold >= 0 && o.ess_threshold <= 1))
    throw InputError(fmt::format("the ESS threshold must be between 0 and 1, not {}", o.ess_threshold));
  if (o.rejuvenation_moves < 0)
    throw InputError(fmt::format("rejuvenation moves must be 0 or more, not {}", o.rejuvenation_moves));
  if (o.proposal_groups < 1)
    throw InputError(fmt::format("proposal groups must be 1 or more, not {}", o.proposal_groups));
}

void Belief::note_deixis(pddl::ActionId action) {
  if (!is_speaker_action(action) || speaker_ < 0) return;
  const auto& ga = task_->action(action);
  const commands::SalientActionRule* rule =
      utterance_model_->config().salient_rule(task_->domain().actions[static_cast<size_t>(ga.schema)].name);
  if (!rule || rule->focal_is_place || rule->focal_arg < 1 || rule->focal_arg > static_cast<int>(ga.args.size())) return;
  const pddl::ObjectId focal = ga.args[static_cast<size_t>(rule->focal_arg - 1)];
  deictic_type_ = task_->domain().types[static_cast<size_t>(task_->problem().objects[static_cast<size_t>(focal)].type)].name;
  deictic_object_ = focal;
}

std::vector<std::string> Belief::resolved(const std::vector<std::string>& utterances, const pddl::State& s) const {
  if (deictic_type_.empty()) return utterances;
  const language::KindNoun kind = language::kind_noun(deictic_type_);
  // "One more of these" is another one than the speaker's: a quality value
  // of that object which no other object of its kind has in s.
  std::string except;
  if (deictic_object_ >= 0) {
    const commands::LanguageConfig& config = utterance_model_->config();
    const int type = task_->problem().objects[static_cast<size_t>(deictic_object_)].type;
    const int value_arg = config.qualifier_object_arg == 1 ? 1 : 0;
    auto values_of = [&](int o) {
      std::vector<std::string> v;
      for (const commands::Term& t : utterance_model_->qualifiers(task_->object_name(o), s))
        if (config.is_qualifier(t.name) && t.args.size() == 2) v.push_back(t.name + " " + t.args[value_arg]);
      return v;
    };
    for (const std::string& pv : values_of(deictic_object_)) {
      bool unique = true;
      for (int o = 0; o < task_->num_objects() && unique; ++o)
        if (o != deictic_object_ && task_->problem().objects[static_cast<size_t>(o)].type == type) {
          const auto others = values_of(o);
          unique = std::find(others.begin(), others.end(), pv) == others.end();
        }
      if (unique) {
        except = pv.substr(pv.find(' ') + 1);
        break;
      }
    }
  }
  std::vector<std::string> out;
  out.reserve(utterances.size());
  for (const std::string& u : utterances) out.push_back(language::resolve_deixis(u, kind, except));
  return out;
}

bool Belief::is_speaker_action(pddl::ActionId a) const {
  // The acting agent is the first argument of every action; without a known
  // speaker object every action counts as evidence.
  const auto& args = task_->action(a).args;
  return speaker_ < 0 || (!args.empty() && args[0] == speaker_);
}

pddl::ObjectId Belief::acting_agent(const pddl::State& s) const {
  const auto acts = task_->applicable_actions(s);
  if (acts.empty()) return -1;
  const auto& args = task_->action(acts.front()).args;
  return args.empty() ? -1 : args[0];
}

void Belief::refine_all(const pddl::State& s, RefineWhat what) {
  std::vector<int> all(policies_.size());
  for (size_t h = 0; h < all.size(); ++h) all[h] = static_cast<int>(h);
  refine_some(s, all, what);
}

Belief::RefineWhat Belief::refine_what(pddl::ActionId action, bool evidence,
                                       const std::vector<std::string>& utterances) const {
  // Scoring the human's action needs every Q-value at s.
  if (evidence || options_.assistant_turns == AssistantTurns::All) return {};
  return {.toward = action, .keep_stored = !utterances.empty()};
}

Belief::RefineWhat Belief::hear_refine_what() const {
  if (options_.assistant_turns == AssistantTurns::All) return {};
  return {.toward = -1, .keep_stored = true};
}

void Belief::refine_some(const pddl::State& s, const std::vector<int>& hs, RefineWhat what) {
  if (!search_) return;  // VH: V = -h_g, nothing to refine
  // Each hypothesis' refinement (toward >= 0: refine_toward); one with a
  // stored plan kept gets what a silent turn gives it, possibly nothing.
  std::vector<std::pair<size_t, pddl::ActionId>> work;
  for (int hi : hs) {
    const size_t h = static_cast<size_t>(hi);
    if (what.keep_stored && policies_[h].on_stored_path(s)) {
      if (what.toward >= 0) work.push_back({h, what.toward});
    } else {
      work.push_back({h, what.keep_stored ? -1 : what.toward});  // no stored plan: the full REFINE
    }
  }
  refinements_ += work.size();
  // Each hypothesis owns its policy and heuristic, so the refinements are
  // independent and may run on several threads.
  budget_stops_.resize(policies_.size(), 0);
  std::atomic<bool> stopped{false};
  auto refine_one = [&](size_t h, pddl::ActionId toward) {
    if (stop_ && (stopped || stop_())) {
      stopped = true;
      return;
    }
    budget_stops_[h] += (toward >= 0 ? policies_[h].refine_toward(s, toward, options_.refine)
                                     : policies_[h].refine_step(s, options_.refine))
                            .stopped_by_budget;
  };
  if (pool_ && work.size() > 1) {
    // Longest first: the step ends when the slowest thread does, and a long
    // refinement started last would leave the other threads idle. Each
    // hypothesis' time is predicted by its last refinement at a state where
    // the same agent acts: with turns, the agents' steps differ (on the
    // paper's maps the assistant's turns take about seven times the human's,
    // per hypothesis unevenly), so the step just before is a poor guide. The
    // order does not change any result.
    std::vector<double>& last = refine_seconds_[acting_agent(s)];
    last.resize(policies_.size(), 0.0);
    std::stable_sort(work.begin(), work.end(), [&](const auto& a, const auto& b) { return last[a.first] > last[b.first]; });
    const auto w0 = std::chrono::steady_clock::now();
    pool_->run(work.size(), [&](size_t i) {
      const auto [h, toward] = work[i];
      const auto t0 = std::chrono::steady_clock::now();
      refine_one(h, toward);
      last[h] = seconds_since(t0);
    });
    const double wall = seconds_since(w0);
    double sum = 0;
    for (const auto& [h, toward] : work) sum += last[h];
    parallel_saved_ += std::max(0.0, sum - wall);
  } else {
    for (const auto& [h, toward] : work) refine_one(h, toward);
  }
  if (stopped) throw Interrupted("stopped between refinements");
}

// How much dearer the assistant's actions are in the progress relaxation:
// enough that h_max measures the principal's own way to each goal atom.
constexpr double kPrincipalAloneFactor = 1000;

// A hypothesis' goal as the principal alone would reach it. Copies of a
// belief share it, hence the lock on its heuristic's buffers.
struct Belief::Progress {
  std::shared_ptr<model::Specification> spec;
  std::mutex lock;
  heuristics::HMaxHeuristic hmax;
  std::vector<int> goal_atoms;
  // The last state asked about and its progressing actions (a twin and its
  // base share this: the assistant's costs do not matter here).
  std::optional<pddl::State> last;
  std::vector<pddl::ActionId> progressing;
};

double Belief::progress_likelihood(int h, const pddl::State& s, const std::vector<pddl::ActionId>& candidates,
                                   pddl::ActionId action) {
  if (progress_.size() != hyps_.size()) progress_.resize(hyps_.size());
  auto& p = progress_[static_cast<size_t>(base_of_[static_cast<size_t>(h)])];
  if (!p) {
    p = std::make_shared<Progress>();
    const domains::Roles& roles = pack_->spec().roles;
    const model::Specification& base = *hyps_[static_cast<size_t>(h)].spec;
    p->spec = std::make_shared<model::Specification>(
        task_, base.goal_text(),
        model::scaled_assistant(base.profile(), base.profile().name + "-progress", roles.assistant, roles.noop_action,
                                kPrincipalAloneFactor));
    p->hmax.prepare(*p->spec, s);
    for (const auto& clause : heuristics::goal_dnf(base.goal(), true))
      for (int b : clause)
        if (std::find(p->goal_atoms.begin(), p->goal_atoms.end(), b) == p->goal_atoms.end()) p->goal_atoms.push_back(b);
  }
  const std::lock_guard<std::mutex> held(p->lock);
  if (!p->last || !(*p->last == s)) {
    p->last = s;
    p->progressing.clear();
    p->hmax.estimate(s.data());
    const std::vector<double> now = p->hmax.atom_costs();
    // Where the goal holds already nothing is progress (and h_max stopped).
    for (pddl::ActionId a : p->spec->is_goal(s) ? std::vector<pddl::ActionId>{} : candidates) {
      const pddl::State next = task_->apply(s, a);
      if (p->spec->is_goal(next)) {  // (h_max stops at a goal state)
        p->progressing.push_back(a);
        continue;
      }
      p->hmax.estimate(next.data());
      const auto& after = p->hmax.atom_costs();
      for (int b : p->goal_atoms)
        if (!pddl::get_bit(s.data(), b) && after[static_cast<size_t>(b)] < now[static_cast<size_t>(b)] - 1e-9) {
          p->progressing.push_back(a);
          break;
        }
    }
  }
  if (p->progressing.empty()) return 1.0 / static_cast<double>(candidates.size());
  const bool chosen = std::find(p->progressing.begin(), p->progressing.end(), action) != p->progressing.end();
  return chosen ? 1.0 / static_cast<double>(p->progressing.size()) : 0.0;
}

double Belief::score_action(int h, const pddl::State& s, pddl::ActionId action) {
  std::vector<double> q;
  std::vector<pddl::ActionId> candidates;
  int chosen = -1;
  for (const search::QValue& qv : policies_[h].q_values(s)) {
    if (qv.action == action) chosen = static_cast<int>(q.size());
    q.push_back(qv.q);
    candidates.push_back(qv.action);
  }
  if (progress_share_ > 0 && chosen >= 0) {
    const double boltzmann = temps_[h].update(q, chosen);
    return std::log((1 - progress_share_) * boltzmann +
                    progress_share_ * progress_likelihood(h, s, candidates, action));
  }
  // An unavailable action has likelihood 0: the hypothesis is eliminated.
  return std::log(temps_[h].update(q, chosen));
}

std::vector<SpeakerPlans> Belief::speaker_plans(const pddl::State& s, const std::vector<int>& hs) {
  // Each distinct speaker once (a twin and its base share theirs).
  std::vector<int> speakers;
  std::vector<size_t> slot(hs.size());
  for (size_t i = 0; i < hs.size(); ++i) {
    const int sp = base_of_[static_cast<size_t>(hs[i])];
    auto it = std::find(speakers.begin(), speakers.end(), sp);
    slot[i] = static_cast<size_t>(it - speakers.begin());
    if (it == speakers.end()) speakers.push_back(sp);
  }
  std::vector<SpeakerPlans> plans(speakers.size());
  const bool tied = search_ && utterance_model_->plans_rule() == domains::RolloutSettings::Plans::Tied;
  auto one = [&](size_t i) {
    search::Policy& p = policies_[static_cast<size_t>(speakers[i])];
    plans[i] = tied ? utterance_model_->speaker_plans(p, s, options_.refine) : utterance_model_->single_plan(p, s);
    if (spare_share_ > 0) {
      SpeakerPlans spare = sparing_plan(static_cast<size_t>(speakers[i]), s);
      if (!spare.empty()) {
        for (SpeakerPlan& plan : plans[i]) plan.weight *= 1 - spare_share_;
        spare.front().weight = spare_share_;
        plans[i].push_back(std::move(spare.front()));
      }
    }
    if (!tied || delegate_of_.empty()) return;
    search::Policy& d = delegates_[static_cast<size_t>(delegate_of_[static_cast<size_t>(speakers[i])])];
    for (SpeakerPlan& plan : plans[i]) plan.weight *= 1 - delegate_share_;
    for (SpeakerPlan& plan : utterance_model_->speaker_plans(d, s, options_.refine)) {
      plan.weight *= delegate_share_;
      plans[i].push_back(std::move(plan));
    }
  };
  if (tied && pool_ && speakers.size() > 1) {
    pool_->run(speakers.size(), one);
  } else {
    for (size_t i = 0; i < speakers.size(); ++i) one(i);
  }
  if (speakers.size() == hs.size()) return plans;
  std::vector<SpeakerPlans> out(hs.size());
  for (size_t i = 0; i < hs.size(); ++i) out[i] = plans[slot[i]];
  return out;
}

std::vector<commands::Command> Belief::goal_statements(const pddl::State& s, const std::vector<int>& hs) const {
  std::vector<commands::Command> out(hs.size());
  if (utterance_model_->config().goal_statements <= 0) return out;
  for (size_t i = 0; i < hs.size(); ++i) {
    const data::GoalSpec& g = goals_[static_cast<size_t>(hyps_[static_cast<size_t>(hs[i])].goal)];
    out[i] = utterance_model_->goal_statement(g.label, g.condition, s);
  }
  return out;
}

std::vector<UtteranceRecord> Belief::score_utterances(const pddl::State& s, const std::vector<std::string>& utterances,
                                                      lm::LanguageModel* lm, bool speak_factor) {
  std::vector<UtteranceRecord> out;
  if (options_.speak_factors && speak_factor) {
    // Goal-independent: they move only the log marginal likelihood.
    const double f = utterances.empty() ? std::log1p(-options_.p_speak) : std::log(options_.p_speak);
    for (double& u : utterance_ll_) u += f;
  }
  if (utterances.empty()) return out;
  if (!lm) throw InputError("an utterance was observed but no language model was given");
  std::vector<int> all(policies_.size());
  for (size_t h = 0; h < all.size(); ++h) all[h] = static_cast<int>(h);
  const std::vector<std::string> texts = resolved(utterances, s);
  auto scores = utterance_model_->score(speaker_plans(s, all), goal_statements(s, all), s, texts, *lm);
  if (request_share_ > 0) read_requests(s, texts, scores, *lm);
  if (std::getenv("CLIPS_DEBUG_UTTERANCE")) {
    // CLIPS_DEBUG_UTTERANCE=1: each hypothesis' likelihood and its most probable readings.
    for (size_t u = 0; u < texts.size(); ++u) {
      std::fprintf(stderr, "utterance \"%s\" read as \"%s\"\n", utterances[u].c_str(), texts[u].c_str());
      for (size_t h = 0; h < scores[u].size(); ++h) {
        const HypothesisUtterance& r = scores[u][h];
        std::fprintf(stderr, "  %s | %s: log L %.2f\n", goals_[static_cast<size_t>(hyps_[h].goal)].label.c_str(),
                     profiles_[static_cast<size_t>(hyps_[h].profile)].name.c_str(), r.log_likelihood);
        std::vector<const CommandScore*> top;
        for (const CommandScore& c : r.commands) top.push_back(&c);
        std::sort(top.begin(), top.end(), [](auto* a, auto* b) { return a->posterior > b->posterior; });
        for (size_t k = 0; k < top.size() && k < 4; ++k)
          std::fprintf(stderr, "    %.3f (lm %.2f, prior %.3f) %s\n", top[k]->posterior, top[k]->log_lm, top[k]->prior,
                       top[k]->command.c_str());
        for (const CommandScore& c : r.requests)
          if (c.posterior > 0.05)
            std::fprintf(stderr, "    request %.3f (lm %.2f) %s\n", c.posterior, c.log_lm, c.command.c_str());
      }
    }
  }
  for (size_t u = 0; u < utterances.size(); ++u) {
    UtteranceRecord rec;
    rec.text = utterances[u];
    rec.hypotheses = std::move(scores[u]);
    rec.log_background = log_background(rec.hypotheses, noise_);
    weigh_utterance(rec);
    if (rec.evidence_weight > 0)
      for (size_t h = 0; h < hyps_.size(); ++h) {
        const double ll = utterance_evidence(rec.hypotheses[h].log_likelihood, rec.log_background);
        // w * ll with w in (0, 1]; a NaN score counts as impossible.
        utterance_ll_[h] += std::isnan(ll) ? kNegInf : (rec.evidence_weight == 1 ? ll : rec.evidence_weight * ll);
      }
    out.push_back(std::move(rec));
  }
  return out;
}

namespace {
// How much dearer a sparing principal's own actions are (Belief::sparing_plan).
constexpr double kSparingFactor = 10;
}  // namespace

SpeakerPlans Belief::plan_for(const model::Specification& spec, const pddl::State& s) {
  std::shared_ptr<heuristics::Heuristic> heur = pack_->make_heuristic(heuristic_name_, *task_);
  heur->prepare(spec, s);
  search::SearchOptions o = options_.refine;
  o.max_nodes = std::min<size_t>(o.max_nodes, size_t{1} << 16);
  const search::SearchResult r = search::astar(spec, *heur, s, o);
  if (r.status != search::SearchStatus::Success) return {};
  return {SpeakerPlan{1.0, r.plan}};
}

SpeakerPlans Belief::sparing_plan(size_t h, const pddl::State& s) {
  SparingMemo& memo = *sparing_memo_;
  {
    std::lock_guard<std::mutex> lock(memo.mu);
    if (memo.state != s) {
      memo.state = s;
      memo.plans.clear();
    }
    if (auto it = memo.plans.find(h); it != memo.plans.end()) return it->second;
  }
  const model::Specification& base = *hyps_[h].spec;
  const domains::Roles& roles = pack_->spec().roles;
  model::Specification spec(task_, base.goal_text(),
                            model::scaled_assistant(base.profile(), base.profile().name + "-sparing", roles.principal,
                                                    roles.noop_action, kSparingFactor));
  SpeakerPlans plans = plan_for(spec, s);
  std::lock_guard<std::mutex> lock(memo.mu);
  if (memo.state == s) memo.plans.emplace(h, plans);
  return plans;
}

SpeakerPlans Belief::handing_plan(size_t h, const pddl::State& s, const SpeakerPlan& sparing) {
  const model::Specification& base = *hyps_[h].spec;
  const domains::Roles& roles = pack_->spec().roles;
  const pddl::Task& task = *task_;
  model::CostProfile profile = model::scaled_assistant(base.profile(), base.profile().name + "-handing",
                                                       roles.principal, roles.noop_action, kSparingFactor);
  std::vector<char> goal_atom(static_cast<size_t>(task.num_atoms()), 0);
  for (const auto& clause : heuristics::goal_dnf(base.goal(), false))
    for (int b : clause)
      if (b >= 0 && b < task.num_atoms()) goal_atom[static_cast<size_t>(b)] = 1;
  for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
    const auto& ga = task.action(a);
    if (ga.args.empty()) continue;
    const std::string agent = task.object_name(ga.args[0]);
    if (agent != roles.principal && agent != roles.assistant) continue;
    if (std::none_of(ga.eff.add.begin(), ga.eff.add.end(), [&](int b) { return goal_atom[static_cast<size_t>(b)] != 0; }))
      continue;
    const std::string& schema = task.domain().actions[ga.schema].name;
    profile.action_factors[{agent, schema}] = agent == roles.principal ? 1 / kSparingFactor : kSparingFactor;
  }
  // Where the sparing plan leaves every such step to the principal, it is
  // this plan already.
  const bool assistant_finishes = std::any_of(sparing.actions.begin(), sparing.actions.end(), [&](pddl::ActionId a) {
    const auto& ga = task.action(a);
    return !ga.args.empty() && task.object_name(ga.args[0]) == roles.assistant &&
           profile.action_factors.count({roles.assistant, task.domain().actions[ga.schema].name}) > 0;
  });
  if (!assistant_finishes) return {};
  model::Specification spec(task_, base.goal_text(), profile);
  return plan_for(spec, s);
}

void Belief::read_requests(const pddl::State& s, const std::vector<std::string>& texts,
                           std::vector<std::vector<HypothesisUtterance>>& scores, lm::LanguageModel& lm) {
  // The plan in which the assistant does all it can for each speaker's goal.
  std::vector<int> speakers;
  std::vector<SpeakerPlans> sparing;
  for (size_t h = 0; h < hyps_.size(); ++h) {
    if (base_of_[h] != static_cast<int>(h)) continue;
    speakers.push_back(static_cast<int>(h));
    SpeakerPlans plans = sparing_plan(h, s);
    // And, half and half, the plan that hands the principal what it fetches.
    SpeakerPlans handing = plans.empty() ? SpeakerPlans{} : handing_plan(h, s, plans.front());
    if (!handing.empty() && handing.front().actions != plans.front().actions) {
      plans.front().weight = handing.front().weight = 0.5;
      plans.push_back(std::move(handing.front()));
    }
    sparing.push_back(std::move(plans));
  }
  auto sparing_scores = utterance_model_->score(sparing, s, texts, lm);
  for (size_t u = 0; u < texts.size(); ++u)
    for (size_t h = 0; h < hyps_.size(); ++h) {
      const size_t k = static_cast<size_t>(std::find(speakers.begin(), speakers.end(), base_of_[h]) - speakers.begin());
      if (k >= sparing.size() || sparing[k].empty()) continue;
      scores[u][h].requests = merge_requests(scores[u][h], sparing_scores[u][k], request_share_);
    }
}

double log_background(const std::vector<HypothesisUtterance>& hs, double noise) {
  if (noise <= 0) return kNegInf;
  double hi = kNegInf;
  size_t n = 0;
  for (const auto& h : hs)
    if (!std::isnan(h.log_likelihood)) {
      hi = std::max(hi, h.log_likelihood);
      ++n;
    }
  if (n == 0 || hi == kNegInf) return kNegInf;
  double z = 0;
  for (const auto& h : hs)
    if (!std::isnan(h.log_likelihood)) z += std::exp(h.log_likelihood - hi);
  return hi + std::log(z / static_cast<double>(n));
}

double Belief::utterance_evidence(double ll, double log_b) const {
  if (noise_ <= 0 || std::isnan(ll) || log_b == kNegInf) return exponent_ * ll;
  const double a = std::log1p(-noise_) + ll, b = std::log(noise_) + log_b;
  const double hi = std::max(a, b);
  return exponent_ * (hi + std::log(std::exp(a - hi) + std::exp(b - hi)));
}

double evidence_weight(double share, const InferenceOptions& o) {
  if (!o.temper_unreadable || share >= o.readable_share_full) return 1;
  if (share <= o.readable_share_none) return 0;
  return (share - o.readable_share_none) / (o.readable_share_full - o.readable_share_none);
}

namespace {

// The utterance as quoted in a warning: at most 60 characters (never cut
// inside a UTF-8 sequence).
std::string quote_utterance(const std::string& text) {
  constexpr size_t kMax = 60;
  if (text.size() <= kMax) return "\"" + text + "\"";
  size_t cut = kMax;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return "\"" + text.substr(0, cut) + "...\" (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace

void Belief::weigh_utterance(UtteranceRecord& rec) const {
  if (!options_.temper_unreadable) return;
  const lm::UtteranceReading reading = lm::read_utterance(rec.text);
  rec.readable_share = reading.share();
  rec.evidence_weight = evidence_weight(rec.readable_share, options_);
  const bool any_possible = std::any_of(rec.hypotheses.begin(), rec.hypotheses.end(), [](const HypothesisUtterance& h) {
    return h.log_likelihood > kNegInf;  // false for -inf and NaN
  });
  if (!any_possible) {
    // Nothing to compare: adding -inf to every hypothesis would wipe out what
    // the actions showed (the posterior fell back to the prior).
    rec.evidence_weight = 0;
    rec.warning = "utterance " + quote_utterance(rec.text) +
                  " has probability 0 under every hypothesis (the language model cannot score it); it is ignored";
  } else if (rec.evidence_weight < 1) {
    const std::string what = reading.words == 0
                                 ? "has no words"
                                 : fmt::format("has {} of {} words the model can read (an English word it knows)",
                                               reading.known, reading.examined);
    rec.warning = "utterance " + quote_utterance(rec.text) + " " + what +
                  (rec.evidence_weight == 0 ? "; it is ignored"
                                            : fmt::format("; its evidence is weighted by {:.2f}", rec.evidence_weight));
  }
}

StepRecord Belief::start(const pddl::State& s0, const std::vector<std::string>& utterances, lm::LanguageModel* lm) {
  const auto t0 = std::chrono::steady_clock::now();
  parallel_saved_ = 0;
  state_ = s0;
  t_ = 0;
  if (particle_mode()) {
    history_.push_back({.kind = Event::Kind::Refine, .state = s0});
    history_.push_back(speak_event(s0, utterances, true));
    auto utts = particle_step(lm);
    return record("", false, std::move(utts), seconds_since(t0));
  }
  refine_all(s0, RefineWhat{});
  auto utts = score_utterances(s0, utterances, lm);
  return record("", false, std::move(utts), seconds_since(t0));
}

StepRecord Belief::observe(pddl::ActionId action, const pddl::State& state, const std::vector<std::string>& utterances,
                           lm::LanguageModel* lm) {
  const auto t0 = std::chrono::steady_clock::now();
  parallel_saved_ = 0;
  const pddl::State s = state;  // `state` may alias state_
  note_deixis(action);
  if (particle_mode()) {
    const bool evidence = is_speaker_action(action);
    const RefineWhat what = refine_what(action, evidence, utterances);
    history_.push_back({.kind = Event::Kind::Refine, .state = s, .action = what.toward, .keep_stored = what.keep_stored});
    if (evidence) history_.push_back({.kind = Event::Kind::Act, .state = s, .action = action});
    history_.push_back(speak_event(s, utterances, true));
    auto utts = particle_step(lm);
    state_ = task_->apply(s, action);
    ++t_;
    return record(task_->action_name(action), evidence, std::move(utts), seconds_since(t0));
  }
  const bool evidence = is_speaker_action(action);
  refine_all(s, refine_what(action, evidence, utterances));
  if (evidence)
    for (size_t h = 0; h < hyps_.size(); ++h) action_ll_[h] += score_action(static_cast<int>(h), s, action);
  // Robot actions: do(a), no evidence and no temperature update.
  auto utts = score_utterances(s, utterances, lm);
  state_ = task_->apply(s, action);
  ++t_;
  return record(task_->action_name(action), evidence, std::move(utts), seconds_since(t0));
}

StepRecord Belief::hear(const std::vector<std::string>& utterances, lm::LanguageModel& lm, StepRecord last) {
  if (utterances.empty()) return last;
  const auto t0 = std::chrono::steady_clock::now();
  parallel_saved_ = 0;
  if (particle_mode()) {
    const RefineWhat what = hear_refine_what();
    history_.push_back({.kind = Event::Kind::Refine, .state = state_, .action = what.toward, .keep_stored = what.keep_stored});
    history_.push_back(speak_event(state_, utterances, false));
    auto utts = particle_step(&lm);
    StepRecord r = record(last.action, last.evidence, std::move(last.utterances), last.seconds);
    for (auto& u : utts) r.utterances.push_back(std::move(u));
    const double more = seconds_since(t0);
    r.seconds += more;
    r.work_seconds = last.work_seconds + more + parallel_saved_;
    return r;
  }
  refine_all(state_, hear_refine_what());
  auto utts = score_utterances(state_, utterances, &lm, /*speak_factor=*/false);
  if (options_.speak_factors) {
    // The step already counted "no utterance"; it had one after all.
    const double fix = std::log(options_.p_speak) - std::log1p(-options_.p_speak);
    for (double& u : utterance_ll_) u += fix;
  }
  StepRecord r = record(last.action, last.evidence, std::move(last.utterances), last.seconds);
  for (auto& u : utts) r.utterances.push_back(std::move(u));
  const double more = seconds_since(t0);
  r.seconds += more;
  r.work_seconds = last.work_seconds + more + parallel_saved_;
  return r;
}

size_t Belief::searches_stopped_by_budget() const {
  size_t n = 0;
  for (size_t x : budget_stops_) n += x;
  return n;
}

Posterior Belief::posterior(Modality m) const {
  if (particle_mode()) return particle_posterior(m);
  Posterior p;
  const size_t n = hyps_.size();
  std::vector<double> lw(n);
  double mx = kNegInf;
  for (size_t h = 0; h < n; ++h) {
    lw[h] = log_prior_[h] + (m == Modality::UtteranceOnly ? 0.0 : action_ll_[h]) +
            (m == Modality::ActionOnly ? 0.0 : utterance_ll_[h]);
    mx = std::max(mx, lw[h]);
  }
  p.hypotheses.assign(n, 0.0);
  if (mx == kNegInf) {
    // Every hypothesis is eliminated: report the prior rather than NaNs.
    p.log_marginal = kNegInf;
    for (size_t h = 0; h < n; ++h) p.hypotheses[h] = std::exp(log_prior_[h]);
  } else {
    double z = 0;
    for (size_t h = 0; h < n; ++h) z += (p.hypotheses[h] = std::exp(lw[h] - mx));
    for (double& x : p.hypotheses) x /= z;
    p.log_marginal = mx + std::log(z);
  }
  p.goals.assign(goals_.size(), 0.0);
  p.profiles.assign(profiles_.size(), 0.0);
  for (size_t h = 0; h < n; ++h) {
    p.goals[hyps_[h].goal] += p.hypotheses[h];
    p.profiles[hyps_[h].profile] += p.hypotheses[h];
  }
  return p;
}

StepRecord Belief::record(std::string action, bool evidence, std::vector<UtteranceRecord> utts, double seconds) const {
  StepRecord r;
  r.t = t_;
  r.action = std::move(action);
  r.evidence = evidence;
  for (Modality m : kModalities) r.posterior[static_cast<int>(m)] = posterior(m);
  r.utterances = std::move(utts);
  r.seconds = seconds;
  r.work_seconds = seconds + parallel_saved_;
  return r;
}

}  // namespace clips::inference
