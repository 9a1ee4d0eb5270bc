#pragma once
// The human's rationality: a Boltzmann policy over
// the joint policy's Q-values with an unknown temperature T. T is discretised
// on a fixed 33-point grid and marginalised exactly ("Rao-Blackwellised"): each
// hypothesis carries a weight vector over the grid that is updated by every
// observed human action, so P(a | s, h) = Σ_k w_k P_{T_k}(a | s).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace clips::inference {

inline constexpr int kNumTemperatures = 33;
using TemperatureWeights = std::array<double, kNumTemperatures>;

// T_k = 2^(-3 + 0.25 (k-1)), k = 1..33: 0.125 ... 32 (β = 1/T from 8 down to 1/32).
const TemperatureWeights& temperature_grid();

// Inverse-gamma(shape, scale) DENSITY evaluated at each grid temperature and
// normalised: w_k ∝ T_k^(-shape-1) exp(-scale / T_k). This is the reference's
// discretisation (no Jacobian, as the reference code does), not a Gamma prior on β.
TemperatureWeights inverse_gamma_prior(double shape, double scale);
// Each domain pack names its shape and scale (PackSpec inference settings).

// log P_T(a | s) for every action, from the Q-values of all available actions:
// log softmax(Q / T) with the maximum subtracted first, so very negative Q are
// stable and Q = -inf gives -inf (probability 0). If every Q is -inf (or the
// list is empty) every entry is -inf.
void boltzmann_log_probs(std::span<const double> q, double temperature, std::vector<double>& out);
std::vector<double> boltzmann_log_probs(std::span<const double> q, double temperature);

// The per-hypothesis temperature posterior.
class TemperatureBelief {
 public:
  explicit TemperatureBelief(const TemperatureWeights& prior) : w_(prior) {}

  const TemperatureWeights& weights() const { return w_; }

  // The marginal likelihood L = Σ_k w_k P_{T_k}(a | s) of the action at
  // `chosen` (index into q; a negative index means "not available": L = 0),
  // without changing the weights.
  double likelihood(std::span<const double> q, int chosen) const;

  // Observes the action: returns L and sets w_k ← w_k P_k / L. When L = 0 the
  // weights reset to UNIFORM (not to the prior, as the reference code does).
  double update(std::span<const double> q, int chosen);

 private:
  // P_{T_k}(chosen) for every k.
  void action_probs(std::span<const double> q, int chosen, TemperatureWeights& p) const;
  TemperatureWeights w_;
};

}  // namespace clips::inference
