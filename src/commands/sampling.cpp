#include "commands/sampling.hpp"

#include <stdexcept>

namespace clips::commands {

std::vector<SampledCommand> systematic_sample(const std::vector<double>& sorted_probabilities, double x,
                                              std::size_t m) {
  if (m == 0) throw std::invalid_argument("systematic_sample: m must be positive");
  const double step = 1.0 / static_cast<double>(m);
  if (!(x >= 0.0 && x < step)) throw std::invalid_argument("systematic_sample: x must lie in [0, 1/m)");

  std::vector<SampledCommand> samples;
  std::size_t placed = 0;
  double point = x;  // advanced by repeated addition, as the reference does
  double cumulative = 0.0;
  for (std::size_t i = 0; i < sorted_probabilities.size() && placed < m; ++i) {
    cumulative += sorted_probabilities[i];
    std::size_t copies = 0;
    while (placed < m && point < cumulative) {
      ++copies;
      ++placed;
      point += step;
    }
    if (copies > 0) samples.push_back({i, static_cast<double>(copies) / static_cast<double>(m)});
  }
  return samples;
}

}  // namespace clips::commands
