// Systematic sampling of ranked commands (spec 9.8).
#include <gtest/gtest.h>

#include "commands/sampling.hpp"

namespace clips::commands {
namespace {

std::vector<std::pair<std::size_t, double>> pairs(const std::vector<SampledCommand>& samples) {
  std::vector<std::pair<std::size_t, double>> out;
  for (const auto& s : samples) out.emplace_back(s.index, s.weight);
  return out;
}

TEST(SystematicSampling, CountsGridPointsPerProbabilityBin) {
  const std::vector<double> probs = {0.5, 0.3, 0.15, 0.05};
  // Points 0.02, 0.12, ..., 0.92: five in [0, .5), three in [.5, .8), two in [.8, .95).
  EXPECT_EQ(pairs(systematic_sample(probs, 0.02)),
            (std::vector<std::pair<std::size_t, double>>{{0, 0.5}, {1, 0.3}, {2, 0.2}}));
  // Points 0.099, ..., 0.999: the last one reaches the least likely command.
  EXPECT_EQ(pairs(systematic_sample(probs, 0.099)),
            (std::vector<std::pair<std::size_t, double>>{{0, 0.5}, {1, 0.3}, {2, 0.1}, {3, 0.1}}));
}

TEST(SystematicSampling, OtherSampleCounts) {
  EXPECT_EQ(pairs(systematic_sample({0.6, 0.4}, 0.3, 2)),
            (std::vector<std::pair<std::size_t, double>>{{0, 0.5}, {1, 0.5}}));
  EXPECT_EQ(pairs(systematic_sample({1.0}, 0.0, 1)), (std::vector<std::pair<std::size_t, double>>{{0, 1.0}}));
}

TEST(SystematicSampling, UnnormalisedProbabilitiesLeavePointsUnused) {
  EXPECT_EQ(pairs(systematic_sample({0.4, 0.2}, 0.05)),
            (std::vector<std::pair<std::size_t, double>>{{0, 0.4}, {1, 0.2}}));
  EXPECT_TRUE(systematic_sample({}, 0.05).empty());
}

TEST(SystematicSampling, RejectsBadDraws) {
  EXPECT_THROW(systematic_sample({1.0}, 0.1), std::invalid_argument);
  EXPECT_THROW(systematic_sample({1.0}, -0.01), std::invalid_argument);
  EXPECT_THROW(systematic_sample({1.0}, 0.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace clips::commands
