#include "inference/particle_belief.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.hpp"

namespace clips::inference {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// log Σ exp(x) (-inf for an empty or all -inf input).
double log_sum_exp(const std::vector<double>& x) {
  double mx = kNegInf;
  for (double v : x) mx = std::max(mx, v);
  if (mx == kNegInf) return kNegInf;
  double s = 0;
  for (double v : x) s += std::exp(v - mx);
  return mx + std::log(s);
}

std::vector<int> sorted_unique(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

util::Choices<ParticleFilters>& particle_filters_choices() {
  static util::Choices<ParticleFilters> table(
      "particle filters",
      {{ParticleFilters::All, "all", "one filter per modality", {}},
       {ParticleFilters::Clips, "clips",
        "only the CLIPS posterior's; the action-only and language-only ones are reweighted from its particles: much "
        "cheaper, but rough where they disagree with CLIPS",
        {}}});
  return table;
}
std::string to_string(ParticleFilters f) { return particle_filters_choices().name(f); }
ParticleFilters parse_particle_filters(const std::string& text) { return particle_filters_choices().parse(text); }

util::Choices<ParticleEstimate>& particle_estimate_choices() {
  static util::Choices<ParticleEstimate> table(
      "particle estimate",
      {{ParticleEstimate::Support, "support", "the exact posterior over the hypotheses the particles hold: no counting noise",
        {}},
       {ParticleEstimate::Weights, "weights", "the weighted particle counts", {}}});
  return table;
}
std::string to_string(ParticleEstimate e) { return particle_estimate_choices().name(e); }
ParticleEstimate parse_particle_estimate(const std::string& text) { return particle_estimate_choices().parse(text); }

util::Choices<Rejuvenation>& rejuvenation_choices() {
  static util::Choices<Rejuvenation> table(
      "rejuvenation schedule",
      {{Rejuvenation::Evidence, "evidence", "after every human action or utterance", {}},
       {Rejuvenation::Utterances, "utterances",
        "after steps with an utterance: cheaper, and enough for instructions that point away from the goals the "
        "actions favoured",
        {}},
       {Rejuvenation::Resampling, "resampling",
        "never else: cheapest, but the particles can stay on goals that new evidence turns against", {}}});
  return table;
}
std::string to_string(Rejuvenation r) { return rejuvenation_choices().name(r); }
Rejuvenation parse_rejuvenation(const std::string& text) { return rejuvenation_choices().parse(text); }

ParticleFilter::ParticleFilter(int goals, int profiles, const ParticleOptions& options)
    : goals_(goals), profiles_(profiles), options_(options), rng_(options.seed) {
  if (goals_ < 1 || profiles_ < 1) throw InputError("particle filter: no hypotheses");
  if (options_.particles < 1) throw InputError("particle filter: the number of particles must be positive");
  if (!(options_.ess_threshold >= 0 && options_.ess_threshold <= 1))
    throw InputError("particle filter: the ESS threshold must be between 0 and 1");
  if (options_.rejuvenation_moves < 0) throw InputError("particle filter: rejuvenation moves must be >= 0");
  if (options_.proposal_groups < 1) throw InputError("particle filter: proposal groups must be >= 1");
  const std::vector<double> uniform(static_cast<size_t>(goals_ * profiles_), 1.0);
  hyp_ = systematic(uniform);
  offset_.assign(hyp_.size(), 0.0);
}

std::vector<int> ParticleFilter::systematic(const std::vector<double>& w) {
  // One uniform draw u; particle i takes the hypothesis whose cumulative
  // weight interval holds (i + u) / N. Each hypothesis gets floor or ceil of
  // N × its share: the lowest-variance of the usual schemes.
  const size_t n = static_cast<size_t>(options_.particles);
  double total = 0;
  for (double x : w) total += x;
  std::vector<int> out(n, 0);
  const double u = rng_.uniform01();
  double acc = 0;
  size_t j = 0;
  for (size_t i = 0; i < n; ++i) {
    const double target = (static_cast<double>(i) + u) / static_cast<double>(n) * total;
    while (j + 1 < w.size() && acc + w[j] <= target) acc += w[j++];
    // Rounding can end the walk on a trailing zero weight: step back.
    size_t pick = j;
    while (pick > 0 && !(w[pick] > 0)) --pick;
    out[i] = static_cast<int>(pick);
  }
  return out;
}

std::vector<double> ParticleFilter::log_weights(const LogLikelihood& ll) const {
  std::vector<double> lw(hyp_.size());
  for (size_t i = 0; i < hyp_.size(); ++i) {
    const double l = ll(hyp_[i]);
    lw[i] = std::isnan(l) || l == kNegInf ? kNegInf : offset_[i] + l;
  }
  return lw;
}

std::vector<int> ParticleFilter::held() const { return sorted_unique(hyp_); }

std::vector<int> ParticleFilter::support(const LogLikelihood& ll) const {
  const std::vector<double> lw = log_weights(ll);
  std::vector<int> out;
  for (size_t i = 0; i < hyp_.size(); ++i)
    if (lw[i] > kNegInf) out.push_back(hyp_[i]);
  return sorted_unique(std::move(out));
}

double ParticleFilter::ess(const LogLikelihood& ll) const {
  const std::vector<double> lw = log_weights(ll);
  double mx = kNegInf;
  for (double v : lw) mx = std::max(mx, v);
  if (mx == kNegInf) return 0;
  double s = 0, s2 = 0;
  for (double v : lw) {
    const double w = std::exp(v - mx);
    s += w;
    s2 += w * w;
  }
  return s * s / s2;
}

bool ParticleFilter::update(const LogLikelihood& ll, const Sync& sync, const Current& current, bool evidence) {
  const std::vector<double> lw = log_weights(ll);
  if (log_sum_exp(lw) == kNegInf) {
    restart(sync);
    return false;
  }
  if (ess(ll) >= options_.ess_threshold * static_cast<double>(size())) {
    if (evidence && options_.rejuvenate_on_evidence) rejuvenate(ll, sync, current);
    return false;
  }
  resample(lw);
  rejuvenate(ll, sync, current);
  return true;
}

void ParticleFilter::resample(const std::vector<double>& lw) {
  const double lse = log_sum_exp(lw);
  std::vector<double> w(lw.size());
  for (size_t i = 0; i < lw.size(); ++i) w[i] = std::exp(lw[i] - lse);
  const std::vector<int> pick = systematic(w);
  // Every new particle carries the mean weight, so the evidence estimate
  // log mean w is unchanged by resampling.
  const double mean = lse - std::log(static_cast<double>(lw.size()));
  std::vector<int> hyp(pick.size());
  std::vector<double> off(pick.size());
  for (size_t i = 0; i < pick.size(); ++i) {
    const size_t p = static_cast<size_t>(pick[i]);
    hyp[i] = hyp_[p];
    off[i] = mean - (lw[p] - offset_[p]);  // lw[p] - offset_[p] = l(h_p), finite here
  }
  hyp_ = std::move(hyp);
  offset_ = std::move(off);
  ++stats_.resamples;
}

void ParticleFilter::propose(size_t i, int h2, const LogLikelihood& ll) {
  const int h = hyp_[i];
  if (h2 == h) return;
  ++stats_.proposed;
  const double l = ll(h), l2 = ll(h2);
  // One uniform draw per proposal, also when the outcome is certain, so the
  // stream does not depend on the likelihood values.
  const double u = rng_.uniform01();
  if (std::isnan(l2) || l2 == kNegInf) return;
  if (l2 >= l || u < std::exp(l2 - l)) {
    offset_[i] += l - l2;  // the particle's weight is unchanged by the move
    hyp_[i] = h2;
    ++stats_.accepted;
  }
}

void ParticleFilter::rejuvenate(const LogLikelihood& ll, const Sync& sync, const Current& current) {
  const size_t groups = static_cast<size_t>(options_.proposal_groups);
  for (int sweep = 0; sweep < options_.rejuvenation_moves; ++sweep) {
    // Exploring move: one involution of the grid per group (see the header).
    std::vector<int> d(groups), e(groups);
    for (size_t b = 0; b < groups; ++b) {
      d[b] = static_cast<int>(rng_.index(static_cast<size_t>(goals_)));
      e[b] = static_cast<int>(rng_.index(static_cast<size_t>(profiles_)));
    }
    auto sigma = [&](size_t i) {
      const size_t b = i % groups;
      const int g = hyp_[i] / profiles_, c = hyp_[i] % profiles_;
      const int g2 = ((d[b] - g) % goals_ + goals_) % goals_;
      const int c2 = ((e[b] - c) % profiles_ + profiles_) % profiles_;
      return g2 * profiles_ + c2;
    };
    std::vector<int> proposals;
    for (size_t i = 0; i < hyp_.size(); ++i)
      if (sigma(i) != hyp_[i]) proposals.push_back(sigma(i));
    proposals = sorted_unique(std::move(proposals));
    if (!proposals.empty()) {
      sync(proposals);  // the proposed hypotheses' full-history likelihoods
      std::vector<int> to(hyp_.size());
      for (size_t i = 0; i < hyp_.size(); ++i) to[i] = sigma(i);  // before any particle moves
      for (size_t i = 0; i < hyp_.size(); ++i) propose(i, to[i], ll);
    }
    // Settling move among the current hypotheses (free: nothing to sync): an
    // independence MH proposal h' ∝ P(h' | data) over that set, which is
    // always accepted (the acceptance ratio is 1), so it is a Gibbs draw.
    const std::vector<int> known = current();
    if (known.size() < 2) continue;
    std::vector<double> cdf(known.size());
    double mx = kNegInf;
    for (int h : known) mx = std::max(mx, ll(h));
    double total = 0;
    for (size_t k = 0; k < known.size(); ++k) cdf[k] = (total += std::exp(ll(known[k]) - mx));
    // Stratified in weight: particle i takes the point at the middle of its
    // share of the total weight, shifted by one common uniform u (mod 1), and
    // the hypothesis whose share of the posterior covers that point. Each
    // particle's point is uniform, so each draw is exactly from the
    // posterior over the set; together they cover it like systematic
    // resampling does, instead of adding multinomial noise at every step.
    const std::vector<double> lw = log_weights(ll);
    const double lse = log_sum_exp(lw);
    const double shift = rng_.uniform01();
    double below = 0;  // normalised weight of the particles before i
    for (size_t i = 0; i < hyp_.size(); ++i) {
      const double wi = lse == kNegInf ? 1.0 / static_cast<double>(hyp_.size()) : std::exp(lw[i] - lse);
      double point = below + wi / 2 + shift;
      below += wi;
      point -= std::floor(point);
      const size_t k = std::min(known.size() - 1,
                                static_cast<size_t>(std::upper_bound(cdf.begin(), cdf.end(), point * total) - cdf.begin()));
      const int h = hyp_[i], h2 = known[k];
      if (h2 == h) continue;
      const double l = ll(h), l2 = ll(h2);
      // A particle already ruled out keeps its zero weight (-inf offset).
      offset_[i] = l == kNegInf ? kNegInf : offset_[i] + (l - l2);
      hyp_[i] = h2;
      ++stats_.settled;
    }
  }
}

void ParticleFilter::restart(const Sync& sync) {
  // Importance sampling from the prior with the whole history's likelihood.
  const std::vector<double> uniform(static_cast<size_t>(goals_ * profiles_), 1.0);
  hyp_ = systematic(uniform);
  offset_.assign(hyp_.size(), 0.0);
  sync(held());
  ++stats_.restarts;
}

std::vector<double> ParticleFilter::posterior(const LogLikelihood& ll, double& log_marginal) const {
  const size_t k = static_cast<size_t>(goals_ * profiles_);
  const std::vector<double> lw = log_weights(ll);
  const double lse = log_sum_exp(lw);
  std::vector<double> p(k, 0.0);
  if (lse == kNegInf) {
    log_marginal = kNegInf;
    std::fill(p.begin(), p.end(), 1.0 / static_cast<double>(k));
    return p;
  }
  log_marginal = lse - std::log(static_cast<double>(lw.size()));
  if (options_.estimate == ParticleEstimate::Weights) {
    for (size_t i = 0; i < lw.size(); ++i) p[static_cast<size_t>(hyp_[i])] += std::exp(lw[i] - lse);
    return p;
  }
  // Exact weights on the held set: ll of every held hypothesis is current.
  const std::vector<int> held = support(ll);
  double mx = kNegInf;
  for (int h : held) mx = std::max(mx, ll(h));
  double total = 0;
  for (int h : held) total += (p[static_cast<size_t>(h)] = std::exp(ll(h) - mx));
  for (int h : held) p[static_cast<size_t>(h)] /= total;
  return p;
}

}  // namespace clips::inference
