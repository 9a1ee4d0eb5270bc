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
//   * Rejuvenation after each resampling, and (by default) after every step
//     with evidence for the modality: `moves` Metropolis-Hastings sweeps.
//     Why not only after resampling: the ESS measures how unequal the held
//     hypotheses' weights are, not how well they explain the data. When
//     evidence turns against every held hypothesis alike (17.1.doors of the
//     paper's set: the actions point to gem3/gem4, the instruction to the
//     red door, hence gem1/gem2), the ESS stays high, nothing is resampled
//     and the filter stays on the wrong goals (total variation 1 from the
//     exact posterior with 64 particles). Moving weighted particles with a
//     posterior-invariant kernel keeps the weighted estimate consistent, so
//     the sweeps may run without resampling first.
//     The particles are dealt into `proposal_groups` groups by index (i mod
//     B). Each sweep draws, per group, one random involution of the
//     hypothesis grid, σ(g, c) = ((d - g) mod G, (e - c) mod C) with d, e
//     uniform, and every particle of the group proposes σ(h), accepted with
//     min(1, exp(l(σ(h)) - l(h))) (the prior is uniform). σ is drawn
//     independently of the particles, and for a fixed σ the proposal is
//     deterministic and its own inverse, so each move is a valid MH step
//     leaving the current posterior invariant; averaged over d, e the
//     proposed goal is uniform over all goals. Sharing σ within a group is
//     what bounds the cost: a sweep brings in at most B new hypotheses per
//     distinct hypothesis held, not one per particle. Several groups keep
//     the particles on one hypothesis from all jumping to the same place
//     (one group for all made the estimate lumpy: whole populations moved
//     together).
//     Each sweep then moves every particle once more, to a hypothesis drawn
//     with probability ∝ its posterior weight among the hypotheses that are
//     already current (their likelihoods known: this costs nothing). As an
//     MH step this is an independence proposal q(h') ∝ π(h') on that set, so
//     its acceptance ratio is 1: a Gibbs draw. It lets the particles settle
//     among hypotheses the exploring move brought in (and those it only
//     proposed: they are current too). With uniform proposals instead, the
//     particles that jumped from gem4 to gem1 on 17.1.doors of the paper's
//     set mostly stayed there although gem2 was three times as likely (TV
//     0.27 from exact with 64 particles). The current set is built from the
//     population's past, i.e. an adaptive kernel; given the set, each move
//     leaves the posterior invariant, as adaptive SMC requires. The draws
//     are stratified by the particles' weights (particle_belief.cpp), so the
//     weighted particles cover that posterior without the noise of
//     independent draws.
//   * If every particle has weight 0 (each held hypothesis is contradicted),
//     the filter restarts from the prior weighted by the full-history
//     likelihoods (importance sampling from the prior); if that also finds
//     nothing, the posterior is the prior, as in the exact belief.
//   * Reported posterior (ParticleEstimate): by default the exact posterior
//     restricted to the hypotheses the particles hold with non-zero weight,
//     P(h) ∝ exp l(h) on that set. The hypotheses are discrete and static and
//     each held one's likelihood is known exactly, so the particles' job is
//     to find the set that carries the posterior mass; counting them as well
//     only adds sampling noise (with 128 hypotheses and 256 particles the
//     counts alone are off by about 0.1 in total variation however good the
//     set is). The error is then the exact mass outside the set. This is the
//     discrete-space filter of Fearnhead & Clifford (2003) without its
//     resampling rule (close to it). `Weights` reports the textbook weighted empirical
//     measure P(h) ≈ Σ_i w_i [h_i = h] / Σ_i w_i instead. Either way the log
//     marginal is log mean w_i.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "util/choices.hpp"
#include "util/rng.hpp"

namespace clips::inference {

// Which of Belief's three modalities keep a filter of their own
// (InferenceOptions::particle_filters).
enum class ParticleFilters { All, Clips };
util::Choices<ParticleFilters>& particle_filters_choices();
std::string to_string(ParticleFilters f);                         // "all", "clips"
ParticleFilters parse_particle_filters(const std::string& text);  // throws InputError

// When Belief runs the rejuvenation sweeps besides after each resampling:
// after every step with evidence for the modality (a human action or an
// utterance), only after steps with an utterance (instructions are what
// can point away from every goal the actions favoured, without lowering the
// ESS), or never.
enum class Rejuvenation { Evidence, Utterances, Resampling };
util::Choices<Rejuvenation>& rejuvenation_choices();
std::string to_string(Rejuvenation r);                    // "evidence", "utterances", "resampling"
Rejuvenation parse_rejuvenation(const std::string& text);  // throws InputError

// How the filter turns its particles into a posterior (see above).
enum class ParticleEstimate { Support, Weights };
util::Choices<ParticleEstimate>& particle_estimate_choices();
std::string to_string(ParticleEstimate e);                         // "support", "weights"
ParticleEstimate parse_particle_estimate(const std::string& text);  // throws InputError

struct ParticleOptions {
  int particles = 0;            // N > 0
  double ess_threshold = 0.5;   // resample when ESS < threshold × N (0: never; 1: every step)
  int rejuvenation_moves = 2;   // MH sweeps after each resampling (0: none)
  bool rejuvenate_on_evidence = true;  // also after every update with evidence (else only after resampling)
  int proposal_groups = 8;      // B: independent proposals per sweep (>= 1)
  ParticleEstimate estimate = ParticleEstimate::Support;
  uint64_t seed = 1;
};

// Counters for tests and the evaluation.
struct ParticleStats {
  int resamples = 0;
  int restarts = 0;        // every particle had weight 0
  long proposed = 0;       // MH proposals that moved to another hypothesis
  long accepted = 0;
  long settled = 0;        // particles moved by the settling (Gibbs) move
};

class ParticleFilter {
 public:
  // Log-likelihood of a hypothesis' whole history (prior excluded: uniform).
  // Belief guarantees the hypotheses passed to `sync` first are current.
  using LogLikelihood = std::function<double(int h)>;
  using Sync = std::function<void(const std::vector<int>& hs)>;
  // The hypotheses whose likelihood is known now (ascending; it includes every
  // hypothesis a particle with non-zero weight holds).
  using Current = std::function<std::vector<int>()>;

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
  // After a step: resample and rejuvenate if the ESS is below the threshold,
  // else rejuvenate if the step had `evidence` for this modality and the
  // options say so (restart if every weight is 0). `sync` is called with the
  // hypotheses whose likelihood is about to be read and may not be current.
  // Returns true if it resampled.
  bool update(const LogLikelihood& ll, const Sync& sync, const Current& current, bool evidence = true);

  // Normalised weight per hypothesis (size goals × profiles; by the options'
  // estimate) and the log marginal likelihood estimate; all-zero weights give
  // the uniform prior and -inf.
  std::vector<double> posterior(const LogLikelihood& ll, double& log_marginal) const;

  const ParticleStats& stats() const { return stats_; }

 private:
  std::vector<double> log_weights(const LogLikelihood& ll) const;
  void resample(const std::vector<double>& lw);
  void rejuvenate(const LogLikelihood& ll, const Sync& sync, const Current& current);
  // One MH move of particle i to h2 (both likelihoods known).
  void propose(size_t i, int h2, const LogLikelihood& ll);
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
