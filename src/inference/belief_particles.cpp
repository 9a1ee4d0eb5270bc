// Belief's particle mode (InferenceOptions::particles > 0): the event history,
// lazy replay of hypotheses, and the three modalities' particle filters.
// belief.hpp describes the design; particle_belief.hpp the filter.
#include <algorithm>
#include <cmath>
#include <limits>

#include "inference/belief.hpp"
#include "util/error.hpp"

namespace clips::inference {

namespace {
constexpr double kNegInf = -std::numeric_limits<double>::infinity();
}  // namespace

Belief::Event Belief::speak_event(const pddl::State& s, const std::vector<std::string>& texts, bool step) const {
  Event e;
  e.kind = Event::Kind::Speak;
  e.state = s;
  e.texts = resolved(texts, s);
  e.said = texts;
  if (options_.speak_factors) {
    // The same goal-independent factors, in the same order, as the exact
    // belief adds them (score_utterances before the texts, hear after).
    if (step)
      e.before = texts.empty() ? std::log1p(-options_.p_speak) : std::log(options_.p_speak);
    else
      e.after = std::log(options_.p_speak) - std::log1p(-options_.p_speak);
  }
  return e;
}

double Belief::modality_ll(Modality m, int h) const {
  switch (m) {
    case Modality::Both: return action_ll_[h] + utterance_ll_[h];
    case Modality::ActionOnly: return action_ll_[h];
    case Modality::UtteranceOnly: return utterance_ll_[h];
  }
  return kNegInf;
}

double Belief::particle_ll(Modality m, int h) const {
  if (tracked(m)) return modality_ll(m, h);
  // Importance weights from the CLIPS filter: a particle of weight w on h
  // targets P(h | actions, utterances); w × L_m(h) / L_both(h) targets
  // P(h | m's data). The offset form does that by reading L_m in place of
  // L_both. Hypotheses CLIPS ruled out are not kept current: weight 0.
  return modality_ll(Modality::Both, h) == kNegInf ? kNegInf : modality_ll(m, h);
}

void Belief::apply_event(const Event& e, const std::vector<int>& hs) {
  switch (e.kind) {
    case Event::Kind::Refine: refine_some(e.state, hs, {.toward = e.action, .keep_stored = e.keep_stored}); return;
    case Event::Kind::Act:
      for (int h : hs) action_ll_[h] += score_action(h, e.state, e.action);
      return;
    case Event::Kind::Speak: break;
  }
  for (int h : hs) utterance_ll_[h] += e.before;
  if (!e.texts.empty()) {
    if (!lm_) throw InputError("replaying an utterance needs the language model that scored it");
    const auto scores =
        utterance_model_->score(speaker_plans(e.state, hs), goal_statements(e.state, hs), e.state, e.texts, *lm_);
    for (size_t u = 0; u < e.texts.size(); ++u) {
      const double w = e.weights.at(u);
      const double log_b = e.backgrounds.at(u);
      if (w > 0)
        for (size_t i = 0; i < hs.size(); ++i) {
          const double ll = utterance_evidence(scores[u][i].log_likelihood, log_b);
          utterance_ll_[hs[i]] += std::isnan(ll) ? kNegInf : (w == 1 ? ll : w * ll);
        }
    }
  }
  for (int h : hs) utterance_ll_[h] += e.after;
}

void Belief::sync(const std::vector<int>& hs, size_t until) {
  std::vector<int> todo;
  for (int h : hs)
    if (cursor_[h] < until) todo.push_back(h);
  std::sort(todo.begin(), todo.end());
  todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
  if (todo.empty()) return;
  // Oldest first; a hypothesis joins the group at its own cursor and then
  // advances with it, so each event is applied once to all that need it
  // (refinements in parallel, utterances in one language-model batch).
  std::stable_sort(todo.begin(), todo.end(), [&](int a, int b) { return cursor_[a] < cursor_[b]; });
  std::vector<int> group;
  size_t next = 0;
  for (size_t e = cursor_[todo.front()]; e < until; ++e) {
    while (next < todo.size() && cursor_[todo[next]] == e) group.push_back(todo[next++]);
    apply_event(history_[e], group);
    for (int h : group) cursor_[h] = e + 1;
  }
}

std::vector<UtteranceRecord> Belief::particle_step(lm::LanguageModel* lm) {
  if (lm) lm_ = lm;
  Event& last = history_.back();  // the step's Speak event
  const bool speak = !last.texts.empty();
  if (speak && !lm) throw InputError("an utterance was observed but no language model was given");
  speak_ll_ += last.before + last.after;
  if (speak) heard_ = true;  // the utterance modality's particles come into play (they held the prior so far)

  // Hypotheses whose weight the step may change: those some active filter
  // holds and has not ruled out (a likelihood of 0 stays 0).
  std::vector<int> need;
  for (Modality m : kModalities) {
    if ((m == Modality::UtteranceOnly && !heard_) || !tracked(m)) continue;
    for (int h : filters_[static_cast<int>(m)].held())
      if (modality_ll(m, h) > kNegInf) need.push_back(h);
  }
  std::sort(need.begin(), need.end());
  need.erase(std::unique(need.begin(), need.end()), need.end());

  std::vector<UtteranceRecord> out;
  const size_t end = history_.size();
  if (!speak) {
    sync(need, end);
  } else {
    // The new utterances' evidence weights are set from the hypotheses
    // scored now (for the exact belief: all of them), then stored in the
    // event for hypotheses that replay it later.
    sync(need, end - 1);
    for (int h : need) utterance_ll_[h] += last.before;
    std::vector<std::vector<HypothesisUtterance>> scores(last.texts.size());
    if (!need.empty())
      scores = utterance_model_->score(speaker_plans(last.state, need), goal_statements(last.state, need), last.state,
                                       last.texts, *lm);
    last.weights.assign(last.texts.size(), 0.0);
    last.backgrounds.assign(last.texts.size(), kNegInf);
    for (size_t u = 0; u < last.texts.size(); ++u) {
      UtteranceRecord rec;
      rec.text = u < last.said.size() ? last.said[u] : last.texts[u];
      // Hypotheses no particle holds are not scored: NaN log-likelihood.
      rec.hypotheses.assign(hyps_.size(), HypothesisUtterance{std::numeric_limits<double>::quiet_NaN(), {}, {}});
      for (size_t i = 0; i < need.size(); ++i) rec.hypotheses[need[i]] = std::move(scores[u][i]);
      rec.log_background = log_background(rec.hypotheses, noise_);
      weigh_utterance(rec);
      last.weights[u] = rec.evidence_weight;
      last.backgrounds[u] = rec.log_background;
      if (rec.evidence_weight > 0)
        for (int h : need) {
          const double ll = utterance_evidence(rec.hypotheses[h].log_likelihood, rec.log_background);
          utterance_ll_[h] += std::isnan(ll) ? kNegInf : (rec.evidence_weight == 1 ? ll : rec.evidence_weight * ll);
        }
      out.push_back(std::move(rec));
    }
    for (int h : need) {
      utterance_ll_[h] += last.after;
      cursor_[h] = end;
    }
  }

  // Evidence this step: a human action (the Act event sits before the Speak
  // event) and/or utterances.
  const bool acted = history_.size() >= 2 && history_[history_.size() - 2].kind == Event::Kind::Act;
  for (Modality m : kModalities) {
    if ((m == Modality::UtteranceOnly && !heard_) || !tracked(m)) continue;
    const bool actions = options_.rejuvenate == Rejuvenation::Evidence;
    const bool evidence = m == Modality::Both ? (acted && actions) || speak
                          : m == Modality::ActionOnly ? acted && actions
                                                      : speak;
    auto ll = [&](int h) { return modality_ll(m, h); };
    auto current = [&] {
      std::vector<int> out;
      for (size_t h = 0; h < hyps_.size(); ++h)
        if (cursor_[h] == history_.size() && ll(static_cast<int>(h)) > kNegInf) out.push_back(static_cast<int>(h));
      return out;
    };
    filters_[static_cast<int>(m)].update(ll, [&](const std::vector<int>& hs) { sync(hs, history_.size()); }, current,
                                         evidence);
  }
  return out;
}

Posterior Belief::particle_posterior(Modality m) const {
  Posterior p;
  if (m == Modality::UtteranceOnly && !heard_) {
    // No utterance yet: the weights are the prior's; the marginal likelihood
    // is the goal-independent speak factors.
    p.hypotheses.assign(hyps_.size(), 0.0);
    for (size_t h = 0; h < hyps_.size(); ++h) p.hypotheses[h] = std::exp(log_prior_[h]);
    p.log_marginal = speak_ll_;
  } else {
    p.hypotheses = filter_for(m).posterior([&](int h) { return particle_ll(m, h); }, p.log_marginal);
  }
  p.goals.assign(goals_.size(), 0.0);
  p.profiles.assign(profiles_.size(), 0.0);
  for (size_t h = 0; h < hyps_.size(); ++h) {
    p.goals[hyps_[h].goal] += p.hypotheses[h];
    p.profiles[hyps_[h].profile] += p.hypotheses[h];
  }
  return p;
}

const ParticleStats* Belief::particle_stats(Modality m) const {
  if (!particle_mode() || (m == Modality::UtteranceOnly && !heard_) || !tracked(m)) return nullptr;
  return &filters_[static_cast<int>(m)].stats();
}

std::vector<int> Belief::support(Modality m) const {
  std::vector<int> all(hyps_.size());
  for (size_t h = 0; h < all.size(); ++h) all[h] = static_cast<int>(h);
  if (!particle_mode() || (m == Modality::UtteranceOnly && !heard_)) return all;
  return filter_for(m).support([&](int h) { return particle_ll(m, h); });
}

void Belief::sync_policies(Modality m) {
  if (!particle_mode()) return;
  sync(support(m), history_.size());
}

void Belief::sync_policies(const std::vector<int>& hs) {
  if (!particle_mode()) return;
  sync(hs, history_.size());
}

}  // namespace clips::inference
