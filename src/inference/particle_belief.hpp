#pragma once
// Sequential Monte Carlo over goal specifications h = (goal, cost profile):
// the particle side of inference::Belief when InferenceOptions::particles > 0.
//
// Why a filter inside Belief rather than a second belief class: every caller
// (run_inference, bench, assistance, the API session, `clips serve`) holds a
// concrete Belief and reads its hypotheses, policies and temperatures by
// hypothesis index. Keeping one class whose weights come either from exact
// enumeration or from particles leaves all of them unchanged. This header has
// only the sampling bookkeeping and knows nothing about planning: Belief
// supplies each hypothesis' full-history log-likelihood (computing it on
// demand, see belief.hpp) and this class decides which hypotheses it needs.
//
// The filter, per modality:
//   * Initialisation: N particles from the uniform prior by systematic
//     sampling (every hypothesis gets floor or ceil of N/K particles, so no
//     hypothesis is missed by chance when N >= K).
//   * Weights: a particle's log weight is offset_i + l(h_i), where l(h) is
//     the hypothesis' full-history log-likelihood in this modality. Because a
//     hypothesis' policy and temperature posterior are deterministic
//     functions of the history, every particle on h gets the same
//     incremental weight l_t(h) - l_{t-1}(h): the offset form applies those
//     increments without storing them (and is exact after MH moves, below).
//   * Resampling: systematic, when ESS = (Σw)² / Σw² < ess_threshold × N;
//     afterwards all weights equal the mean weight, so the running log
//     marginal likelihood estimate (log of the mean weight) is preserved.
//   * Rejuvenation after each resampling: `moves` Metropolis-Hastings sweeps.
//     Each sweep draws one random involution of the hypothesis grid,
//     σ(g, c) = ((d - g) mod G, (e - c) mod C) with d, e uniform, and every
//     particle proposes σ(h), accepted with min(1, exp(l(σ(h)) - l(h))) (the
//     prior is uniform). For a fixed σ the proposal is deterministic and its
//     own inverse, so each particle's move is a valid MH step leaving the
//     current posterior invariant; averaged over d, e the proposed goal is
//     uniform over all goals. Sharing σ across particles is what keeps the
//     cost down: a sweep brings in at most one new hypothesis per distinct
//     hypothesis held, not one per particle.
//   * If every particle has weight 0 (each held hypothesis is contradicted),
//     the filter restarts from the prior weighted by the full-history
//     likelihoods (importance sampling from the prior); if that also finds
//     nothing, the posterior is the prior, as in the exact belief.
//   * Reported posterior: the weighted empirical measure of the particles,
//     P(h) ≈ Σ_i w_i [h_i = h] / Σ_i w_i, and log marginal ≈ log mean w_i.
#include <cstdint>
#include <functional>
#include <vector>

#include "util/rng.hpp"

namespace clips::inference {

struct ParticleOptions {
  int particles = 0;            // N > 0
  double ess_threshold = 0.5;   // resample when ESS < threshold × N (0: never; 1: every step)
  int rejuvenation_moves = 2;   // MH sweeps after each resampling (0: none)
  uint64_t seed = 1;
};

// Counters for tests and the evaluation.
struct ParticleStats {
  int resamples = 0;
  int restarts = 0;        // every particle had weight 0
  long proposed = 0;       // MH proposals that moved to another hypothesis
  long accepted = 0;
};

class ParticleFilter {
 public:
  // Log-likelihood of a hypothesis' whole history (prior excluded: uniform).
  // Belief guarantees the hypotheses passed to `sync` first are current.
  using LogLikelihood = std::function<double(int h)>;
  using Sync = std::function<void(const std::vector<int>& hs)>;

  // `goals` × `profiles` hypotheses, numbered goal * profiles + profile.
  ParticleFilter(int goals, int profiles, const ParticleOptions& options);

  int size() const { return static_cast<int>(hyp_.size()); }
  const std::vector<int>& particles() const { return hyp_; }
  // Distinct hypotheses of the particles with non-zero weight, ascending.
  // `ll` must be defined for them (their weights depend on it).
  std::vector<int> support(const LogLikelihood& ll) const;
  // Distinct hypotheses held by any particle, ascending (no likelihood needed).
  std::vector<int> held() const;

  double ess(const LogLikelihood& ll) const;
  // After new evidence: resample and rejuvenate if the ESS is below the
  // threshold (restart if every weight is 0). `sync` is called with the
  // hypotheses whose likelihood is about to be read and may not be current.
  // Returns true if it resampled.
  bool update(const LogLikelihood& ll, const Sync& sync);

  // Normalised weight per hypothesis (size goals × profiles) and the log
  // marginal likelihood estimate; all-zero weights give the uniform prior and
  // -inf.
  std::vector<double> posterior(const LogLikelihood& ll, double& log_marginal) const;

  const ParticleStats& stats() const { return stats_; }

 private:
  std::vector<double> log_weights(const LogLikelihood& ll) const;
  void resample(const std::vector<double>& lw);
  void rejuvenate(const LogLikelihood& ll, const Sync& sync);
  void restart(const Sync& sync);
  // Systematic draw of size() indices from weights proportional to `w`.
  std::vector<int> systematic(const std::vector<double>& w);

  int goals_, profiles_;
  ParticleOptions options_;
  util::Rng rng_;
  std::vector<int> hyp_;         // per particle: hypothesis index
  std::vector<double> offset_;   // per particle: log weight minus l(h)
  ParticleStats stats_;
};

}  // namespace clips::inference
