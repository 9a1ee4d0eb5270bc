#include "eval/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace clips::eval {

double assist_precision(const std::map<std::string, double>& chosen, const std::vector<std::string>& truth) {
  double total = 0, hit = 0;
  for (auto& [o, p] : chosen) {
    total += p;
    if (std::find(truth.begin(), truth.end(), o) != truth.end()) hit += p;
  }
  return total > 0 ? hit / total : 0.0;
}

double assist_recall(const std::map<std::string, double>& chosen, const std::vector<std::string>& truth) {
  if (truth.empty()) return 0.0;
  double hit = 0;
  for (auto& o : truth)
    if (auto it = chosen.find(o); it != chosen.end()) hit += it->second;
  return hit / static_cast<double>(truth.size());
}

MeanSe mean_se(const std::vector<double>& xs) {
  MeanSe m;
  m.n = static_cast<int>(xs.size());
  if (xs.empty()) return m;
  for (double x : xs) m.mean += x;
  m.mean /= m.n;
  if (m.n > 1) {
    double ss = 0;
    for (double x : xs) ss += (x - m.mean) * (x - m.mean);
    m.se = std::sqrt(ss / (m.n - 1)) / std::sqrt(static_cast<double>(m.n));
  }
  return m;
}

}  // namespace clips::eval
