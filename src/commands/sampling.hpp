#pragma once
// Systematic sampling of commands.
#include <cstddef>
#include <vector>

namespace clips::commands {

struct SampledCommand {
  std::size_t index;  // position in the sorted command list
  double weight;      // copies / m
};

// Walks the probabilities (sorted by decreasing probability, as the caller
// ranked its commands) and places m points at x, x + 1/m, ..., x + (m-1)/m with
// x drawn from [0, 1/m). Each command whose cumulative-probability bin holds
// n_c > 0 points is returned once with weight n_c/m. Points beyond the total
// probability (unnormalised lists, rounding) fall on no command, so the
// weights may sum to less than 1. Throws std::invalid_argument unless m > 0
// and 0 <= x < 1/m.
std::vector<SampledCommand> systematic_sample(const std::vector<double>& sorted_probabilities, double x,
                                              std::size_t m = 10);

}  // namespace clips::commands
