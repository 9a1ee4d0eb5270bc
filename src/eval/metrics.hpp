#pragma once
// Per-plan metrics (the paper's; docs/results.md) and their aggregation.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace clips::eval {

// precision = sum of p over true options / sum of p (0 when nothing chosen);
// recall = sum of p over true options / |true options|.
double assist_precision(const std::map<std::string, double>& chosen, const std::vector<std::string>& truth);
double assist_recall(const std::map<std::string, double>& chosen, const std::vector<std::string>& truth);

struct MeanSe {
  double mean = 0, se = 0;
  int n = 0;
};
// Mean and standard error of the mean (sample sd / sqrt(n)).
MeanSe mean_se(const std::vector<double>& xs);

}  // namespace clips::eval
