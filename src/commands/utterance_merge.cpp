#include "commands/utterance_merge.hpp"

#include <algorithm>

namespace clips::commands {

std::vector<RankedCommand> probable_prefix(const std::vector<RankedCommand>& sorted, double threshold) {
  std::vector<RankedCommand> prefix;
  double cumulative = 0.0;
  for (const auto& entry : sorted) {
    prefix.push_back(entry);
    cumulative += entry.probability;
    if (cumulative >= threshold) break;
  }
  return prefix;
}

std::vector<RankedCommand> combine_utterance_rankings(const std::vector<RankedCommand>& kept,
                                                      const std::vector<RankedCommand>& next, double threshold) {
  std::vector<RankedCommand> combined;
  for (const auto& later : probable_prefix(next, threshold))
    for (const auto& earlier : kept)
      combined.push_back({merge_commands(earlier.command, later.command), earlier.probability * later.probability,
                          earlier.score + later.score});
  std::stable_sort(combined.begin(), combined.end(),
                   [](const RankedCommand& a, const RankedCommand& b) { return a.score > b.score; });
  return combined;
}

}  // namespace clips::commands
