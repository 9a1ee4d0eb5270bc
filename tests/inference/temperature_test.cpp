#include "inference/temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

namespace clips::inference {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// The priors the two paper domains' packs name (clips-spec.md 6, VH spec 5).
const TemperatureWeights& dkg_temperature_prior() {
  static const TemperatureWeights w = inverse_gamma_prior(0.5, 1.0);
  return w;
}
const TemperatureWeights& vh_temperature_prior() {
  static const TemperatureWeights w = inverse_gamma_prior(1.0, 2.0);
  return w;
}

TEST(TemperatureGrid, ThirtyThreePointsFromOneEighthTo32) {
  const auto& g = temperature_grid();
  EXPECT_DOUBLE_EQ(g.front(), 0.125);
  EXPECT_DOUBLE_EQ(g[12], 1.0);
  EXPECT_DOUBLE_EQ(g.back(), 32.0);
  EXPECT_NEAR(g[10], 0.707107, 1e-6);
}

TEST(TemperaturePrior, DkgMatchesSpecTable) {
  // clips-spec.md 6: inverse-gamma(0.5, 1) density on the T grid, normalised.
  const double table[kNumTemperatures] = {
      0.00149, 0.00410, 0.00923, 0.01750, 0.02877, 0.04192, 0.05520, 0.06676, 0.07516, 0.07967, 0.08028,
      0.07752, 0.07223, 0.06530, 0.05756, 0.04967, 0.04210, 0.03515, 0.02898, 0.02364, 0.01911, 0.01534,
      0.01223, 0.00970, 0.00766, 0.00602, 0.00472, 0.00369, 0.00288, 0.00224, 0.00175, 0.00136, 0.00105};
  const auto& w = dkg_temperature_prior();
  for (int k = 0; k < kNumTemperatures; ++k) EXPECT_NEAR(w[k], table[k], 5e-6) << "k=" << k;
  EXPECT_NEAR(w[0], 0.00149, 5e-6);    // T = 0.125
  EXPECT_NEAR(w[10], 0.08028, 5e-6);   // T = 0.707
  EXPECT_NEAR(w[32], 0.00105, 5e-6);   // T = 32
  EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-12);
}

TEST(TemperaturePrior, VhMatchesAppendixA1) {
  const auto& w = vh_temperature_prior();
  EXPECT_NEAR(w[0], 5.00009e-06, 1e-10);
  EXPECT_NEAR(w[10], 0.0820671, 1e-7);
  EXPECT_NEAR(w[12], 0.0939551, 1e-7);
  EXPECT_NEAR(w[32], 0.000636892, 1e-9);
}

TEST(Boltzmann, NormalisedAndStable) {
  std::vector<double> q = {-1000.0, -1001.5, -1003.0, kNegInf};
  for (double T : temperature_grid()) {
    auto lp = boltzmann_log_probs(q, T);
    double z = 0;
    for (double x : lp) z += std::exp(x);
    EXPECT_NEAR(z, 1.0, 1e-12) << "T=" << T;
    EXPECT_EQ(lp[3], kNegInf);
    EXPECT_GT(lp[0], lp[1]);
  }
  // VH spec A.3: Q = (-5, -4, -5, -5, -5, -5) at T = 1 gives 1 / (1 + 5/e).
  auto lp = boltzmann_log_probs(std::vector<double>{-5, -4, -5, -5, -5, -5}, 1.0);
  EXPECT_NEAR(std::exp(lp[1]), 0.352187, 1e-6);
  // Nothing possible: every entry -inf.
  for (double x : boltzmann_log_probs(std::vector<double>{kNegInf, kNegInf}, 1.0)) EXPECT_EQ(x, kNegInf);
}

TEST(TemperatureBelief, RaoBlackwellisedUpdate) {
  TemperatureBelief b(dkg_temperature_prior());
  std::vector<double> q = {-8.2, -10.8, -8.8};
  double expected = 0;
  TemperatureWeights post{};
  for (int k = 0; k < kNumTemperatures; ++k) {
    double p = std::exp(boltzmann_log_probs(q, temperature_grid()[k])[0]);
    expected += dkg_temperature_prior()[k] * p;
    post[k] = dkg_temperature_prior()[k] * p;
  }
  EXPECT_NEAR(b.likelihood(q, 0), expected, 1e-15);
  EXPECT_NEAR(b.update(q, 0), expected, 1e-15);
  for (int k = 0; k < kNumTemperatures; ++k) EXPECT_NEAR(b.weights()[k], post[k] / expected, 1e-14);
  // The best action was taken: low temperatures gain weight.
  EXPECT_GT(b.weights()[0], dkg_temperature_prior()[0]);
}

TEST(TemperatureBelief, ResetsToUniformWhenImpossible) {
  TemperatureBelief b(dkg_temperature_prior());
  std::vector<double> q = {-1.0, kNegInf};
  EXPECT_EQ(b.update(q, 1), 0.0);  // a dead-end action
  for (double w : b.weights()) EXPECT_DOUBLE_EQ(w, 1.0 / kNumTemperatures);
  TemperatureBelief c(dkg_temperature_prior());
  EXPECT_EQ(c.update(q, -1), 0.0);  // not available at all
  for (double w : c.weights()) EXPECT_DOUBLE_EQ(w, 1.0 / kNumTemperatures);
}

}  // namespace
}  // namespace clips::inference
