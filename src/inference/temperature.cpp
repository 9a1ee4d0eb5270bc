#include "inference/temperature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clips::inference {

namespace {
constexpr double kNegInf = -std::numeric_limits<double>::infinity();
}

const TemperatureWeights& temperature_grid() {
  static const TemperatureWeights grid = [] {
    TemperatureWeights g{};
    for (int k = 0; k < kNumTemperatures; ++k) g[k] = std::exp2(-3.0 + 0.25 * k);
    return g;
  }();
  return grid;
}

TemperatureWeights inverse_gamma_prior(double shape, double scale) {
  const auto& grid = temperature_grid();
  TemperatureWeights w{};
  // Work in logs: T^(-shape-1) exp(-scale/T) underflows for no grid point, but
  // logs keep the normalisation exact to the last bit anyway.
  double m = kNegInf;
  for (int k = 0; k < kNumTemperatures; ++k) {
    w[k] = (-shape - 1.0) * std::log(grid[k]) - scale / grid[k];
    m = std::max(m, w[k]);
  }
  double z = 0;
  for (double& x : w) z += (x = std::exp(x - m));
  for (double& x : w) x /= z;
  return w;
}

void boltzmann_log_probs(std::span<const double> q, double temperature, std::vector<double>& out) {
  out.assign(q.size(), kNegInf);
  double m = kNegInf;
  for (double x : q) m = std::max(m, x);
  if (m == kNegInf) return;  // nothing is possible
  double z = 0;
  for (double x : q) z += std::exp((x - m) / temperature);  // exp(-inf) = 0
  const double log_z = std::log(z);
  for (size_t i = 0; i < q.size(); ++i)
    if (q[i] != kNegInf) out[i] = (q[i] - m) / temperature - log_z;
}

std::vector<double> boltzmann_log_probs(std::span<const double> q, double temperature) {
  std::vector<double> out;
  boltzmann_log_probs(q, temperature, out);
  return out;
}

void TemperatureBelief::action_probs(std::span<const double> q, int chosen, TemperatureWeights& p) const {
  p.fill(0.0);
  if (chosen < 0 || static_cast<size_t>(chosen) >= q.size() || q[chosen] == kNegInf) return;
  double m = kNegInf;
  for (double x : q) m = std::max(m, x);
  const auto& grid = temperature_grid();
  // Shifted Q-values are computed once; each temperature then costs one exp per action.
  const double dc = q[chosen] - m;
  for (int k = 0; k < kNumTemperatures; ++k) {
    const double beta = 1.0 / grid[k];
    double z = 0;
    for (double x : q) z += std::exp((x - m) * beta);
    p[k] = std::exp(dc * beta) / z;
  }
}

double TemperatureBelief::likelihood(std::span<const double> q, int chosen) const {
  TemperatureWeights p;
  action_probs(q, chosen, p);
  double l = 0;
  for (int k = 0; k < kNumTemperatures; ++k) l += w_[k] * p[k];
  return l;
}

double TemperatureBelief::update(std::span<const double> q, int chosen) {
  TemperatureWeights p;
  action_probs(q, chosen, p);
  double l = 0;
  for (int k = 0; k < kNumTemperatures; ++k) l += w_[k] * p[k];
  if (l > 0) {
    for (int k = 0; k < kNumTemperatures; ++k) w_[k] = w_[k] * p[k] / l;
  } else {
    w_.fill(1.0 / kNumTemperatures);
  }
  return l;
}

}  // namespace clips::inference
