#include "eval/breakdown.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace clips::eval {

namespace {

constexpr int kBins = 10;
const char* const kSplits[] = {"dev", "test"};

// Methods in order of first appearance.
std::vector<std::string> method_order(const BenchReport& r) {
  std::vector<std::string> out;
  for (const auto& p : r.plans)
    for (const auto& m : p.methods)
      if (std::find(out.begin(), out.end(), m.method) == out.end()) out.push_back(m.method);
  return out;
}

bool usable(const PlanOutcome& p, const MethodResult* m) { return p.error.empty() && m && m->error.empty(); }

// The method's goal posterior after the instruction (the final one when the
// plan has no instruction or the step is out of range).
const std::vector<double>* after_instruction(const PlanOutcome& p, const MethodResult& m) {
  if (m.posterior_steps.empty()) return m.goal_posterior.empty() ? nullptr : &m.goal_posterior;
  const int k = p.instruction_step;
  if (k >= 0 && k < static_cast<int>(m.posterior_steps.size())) return &m.posterior_steps[static_cast<size_t>(k)];
  return &m.posterior_steps.back();
}

Calibration calibrate(const BenchReport& r, const std::string& method, const std::string& split) {
  Calibration c;
  c.method = method;
  c.split = split;
  std::vector<double> sum_p(kBins, 0), sum_y(kBins, 0);
  std::vector<int> n(kBins, 0);
  for (const auto& p : r.plans) {
    if (!split.empty() && p.split != split) continue;
    const MethodResult* m = p.find(method);
    if (!usable(p, m) || p.true_goal < 0) continue;
    const std::vector<double>* post = after_instruction(p, *m);
    if (!post) continue;
    for (size_t g = 0; g < post->size(); ++g) {
      const double q = std::clamp((*post)[g], 0.0, 1.0);
      const int b = std::min(kBins - 1, static_cast<int>(q * kBins));
      sum_p[static_cast<size_t>(b)] += q;
      sum_y[static_cast<size_t>(b)] += static_cast<int>(g) == p.true_goal ? 1.0 : 0.0;
      ++n[static_cast<size_t>(b)];
      ++c.forecasts;
    }
  }
  for (int b = 0; b < kBins; ++b) {
    ReliabilityBin bin;
    bin.lo = static_cast<double>(b) / kBins;
    bin.hi = static_cast<double>(b + 1) / kBins;
    bin.n = n[static_cast<size_t>(b)];
    if (bin.n > 0) {
      bin.mean_p = sum_p[static_cast<size_t>(b)] / bin.n;
      bin.frequency = sum_y[static_cast<size_t>(b)] / bin.n;
      c.ece += static_cast<double>(bin.n) / c.forecasts * std::abs(bin.frequency - bin.mean_p);
    }
    c.bins.push_back(bin);
  }
  return c;
}

}  // namespace

Breakdown breakdown(const BenchReport& r) {
  Breakdown b;
  const std::vector<std::string> methods = method_order(r);
  const bool has_splits = std::any_of(r.plans.begin(), r.plans.end(), [](const PlanOutcome& p) { return !p.split.empty(); });
  std::set<std::string> categories;
  for (const auto& p : r.plans) categories.insert(p.categories.begin(), p.categories.end());
  std::vector<std::string> inference_methods;
  for (const auto& m : methods)
    for (const auto& p : r.plans)
      if (const MethodResult* mr = p.find(m); usable(p, mr) && mr->p_true_goal) {
        inference_methods.push_back(m);
        break;
      }

  if (has_splits)
    for (const char* split : kSplits)
      for (const auto& m : methods) {
        SplitRow row;
        row.split = split;
        row.method = m;
        std::map<std::string, std::vector<double>> xs;
        for (const auto& p : r.plans) {
          const MethodResult* mr = p.find(m);
          if (p.split != split || !usable(p, mr)) continue;
          ++row.n;
          if (mr->p_true_goal) xs["p_true_goal"].push_back(*mr->p_true_goal);
          xs["assist_precision"].push_back(mr->precision);
          xs["assist_recall"].push_back(mr->recall);
        }
        if (row.n == 0) continue;
        for (auto& [k, v] : xs) row.metrics[k] = mean_se(v);
        b.splits.push_back(std::move(row));
      }

  for (const std::string& split : has_splits ? std::vector<std::string>{"", "test"} : std::vector<std::string>{""})
    for (const auto& c : categories) {
      CategoryRow row;
      row.category = c;
      row.split = split;
      std::map<std::string, std::vector<double>> pt, pr;
      for (const auto& p : r.plans) {
        if (std::find(p.categories.begin(), p.categories.end(), c) == p.categories.end()) continue;
        if (!split.empty() && p.split != split) continue;
        ++row.n;
        for (const auto& m : methods) {
          const MethodResult* mr = p.find(m);
          if (!usable(p, mr)) continue;
          if (mr->p_true_goal) pt[m].push_back(*mr->p_true_goal);
          pr[m].push_back(mr->precision);
        }
      }
      if (row.n == 0) continue;
      for (auto& [m, v] : pt) row.p_true_goal[m] = mean_se(v).mean;
      for (auto& [m, v] : pr) row.precision[m] = mean_se(v).mean;
      b.categories.push_back(std::move(row));
    }

  for (const auto& m : inference_methods) {
    b.calibration.push_back(calibrate(r, m, ""));
    if (has_splits) b.calibration.push_back(calibrate(r, m, "test"));
  }
  return b;
}

std::string breakdown_table(const Breakdown& b) {
  std::string out;
  auto cell = [](const std::map<std::string, MeanSe>& m, const char* key) {
    auto it = m.find(key);
    return it == m.end() ? std::string("      –     ") : fmt::format("{:.2f} ({:.2f})", it->second.mean, it->second.se);
  };
  if (!b.splits.empty()) {
    out += "\nBy split (instructions.tsv; tune on dev, report test):\n";
    out += fmt::format("{:<6}{:<24}{:>4}  {:^12}  {:^12}  {:^12}\n", "split", "method", "n", "P(g_true)", "precision",
                       "recall");
    for (const auto& row : b.splits)
      out += fmt::format("{:<6}{:<24}{:>4}  {:^12}  {:^12}  {:^12}\n", row.split, row.method, row.n,
                         cell(row.metrics, "p_true_goal"), cell(row.metrics, "assist_precision"),
                         cell(row.metrics, "assist_recall"));
  }
  if (!b.categories.empty()) {
    // The inference methods' P(g_true) and every method's precision, per category.
    std::vector<std::string> pt_methods, pr_methods;
    for (const auto& row : b.categories) {
      for (const auto& [m, v] : row.p_true_goal)
        if (std::find(pt_methods.begin(), pt_methods.end(), m) == pt_methods.end()) pt_methods.push_back(m);
      for (const auto& [m, v] : row.precision)
        if (std::find(pr_methods.begin(), pr_methods.end(), m) == pr_methods.end()) pr_methods.push_back(m);
    }
    out += "\nBy instruction category (mean over the plans of the category; P = P(g_true), prec = precision):\n";
    // Columns as wide as their longest entry: no name is cut or runs into the next.
    size_t cat_w = std::string("category").size();
    for (const auto& row : b.categories) cat_w = std::max(cat_w, row.category.size());
    std::vector<std::string> labels;
    for (const auto& m : pt_methods) labels.push_back("P " + m);
    for (const auto& m : pr_methods) labels.push_back("prec " + m);
    std::vector<size_t> widths;
    for (const auto& l : labels) widths.push_back(std::max<size_t>(6, l.size()));
    std::string head = fmt::format("{:<{}}  {:<5} {:>3}", "category", cat_w, "split", "n");
    for (size_t i = 0; i < labels.size(); ++i) head += fmt::format(" {:>{}}", labels[i], widths[i]);
    out += head + "\n";
    for (const auto& row : b.categories) {
      std::string line = fmt::format("{:<{}}  {:<5} {:>3}", row.category, cat_w, row.split.empty() ? "all" : row.split, row.n);
      size_t col = 0;
      auto value = [&](const std::map<std::string, double>& values, const std::string& m) {
        auto it = values.find(m);
        const size_t w = widths[col++];
        line += it == values.end() ? fmt::format(" {:>{}}", "–", w) : fmt::format(" {:>{}.2f}", it->second, w);
      };
      for (const auto& m : pt_methods) value(row.p_true_goal, m);
      for (const auto& m : pr_methods) value(row.precision, m);
      out += line + "\n";
    }
  }
  if (!b.calibration.empty()) {
    out += "\nCalibration of the goal posterior after the instruction (expected calibration error over every "
           "goal's probability, 10 bins):\n";
    for (const auto& c : b.calibration)
      out += fmt::format("  {:<24}{:<5} ECE {:.3f} ({} forecasts)\n", c.method, c.split.empty() ? "all" : c.split,
                         c.ece, c.forecasts);
  }
  return out;
}

nlohmann::ordered_json breakdown_json(const Breakdown& b) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  auto metrics = [](const std::map<std::string, MeanSe>& m) {
    nlohmann::ordered_json o = nlohmann::ordered_json::object();
    for (const auto& [k, v] : m) o[k] = {{"mean", v.mean}, {"se", v.se}};
    return o;
  };
  if (!b.splits.empty()) {
    nlohmann::ordered_json s = nlohmann::ordered_json::object();
    for (const auto& row : b.splits) {
      nlohmann::ordered_json m = metrics(row.metrics);
      m["n"] = row.n;
      s[row.split][row.method] = std::move(m);
    }
    j["splits"] = std::move(s);
  }
  if (!b.categories.empty()) {
    nlohmann::ordered_json c = nlohmann::ordered_json::array();
    for (const auto& row : b.categories)
      c.push_back({{"category", row.category},
                   {"split", row.split.empty() ? "all" : row.split},
                   {"n", row.n},
                   {"p_true_goal", row.p_true_goal},
                   {"assist_precision", row.precision}});
    j["categories"] = std::move(c);
  }
  if (!b.calibration.empty()) {
    nlohmann::ordered_json c = nlohmann::ordered_json::array();
    for (const auto& cal : b.calibration) {
      nlohmann::ordered_json bins = nlohmann::ordered_json::array();
      for (const auto& bin : cal.bins)
        bins.push_back({{"lo", bin.lo}, {"hi", bin.hi}, {"n", bin.n}, {"mean_p", bin.mean_p}, {"frequency", bin.frequency}});
      c.push_back({{"method", cal.method},
                   {"split", cal.split.empty() ? "all" : cal.split},
                   {"forecasts", cal.forecasts},
                   {"ece", cal.ece},
                   {"bins", std::move(bins)}});
    }
    j["calibration"] = std::move(c);
  }
  return j;
}

std::string reliability_svg(const Calibration& c) {
  const int size = 220, pad = 34;
  const double span = size - 2.0 * pad;
  auto X = [&](double p) { return pad + p * span; };
  auto Y = [&](double p) { return size - pad - p * span; };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{0}\" viewBox=\"0 0 {0} {0}\" role=\"img\" "
      "aria-label=\"reliability diagram of {1}\">\n",
      size, c.method);
  svg += fmt::format("<text x=\"{}\" y=\"14\" class=\"ct\">{} ({}; ECE {:.3f})</text>\n", 4, c.method,
                     c.split.empty() ? "all plans" : c.split, c.ece);
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{:.0f}\" height=\"{:.0f}\" fill=\"none\" stroke=\"#bbb\"/>\n", pad,
                     pad, span, span);
  svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#999\" "
                     "stroke-dasharray=\"4 3\"/>\n",
                     X(0), Y(0), X(1), Y(1));
  for (double t : {0.0, 0.5, 1.0}) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" class=\"ax\" text-anchor=\"middle\">{:g}</text>\n", X(t),
                       size - pad + 12, t);
    svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" class=\"ax\" text-anchor=\"end\">{:g}</text>\n", pad - 4, Y(t) + 3, t);
  }
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" class=\"ax\" text-anchor=\"middle\">predicted probability</text>\n",
                     X(0.5), size - 6);
  svg += fmt::format("<text x=\"10\" y=\"{:.1f}\" class=\"ax\" transform=\"rotate(-90 10 {:.1f})\" "
                     "text-anchor=\"middle\">observed frequency</text>\n",
                     Y(0.5), Y(0.5));
  std::string pts;
  for (const auto& bin : c.bins) {
    if (bin.n == 0) continue;
    pts += fmt::format("{:.1f},{:.1f} ", X(bin.mean_p), Y(bin.frequency));
    // Dot area grows with the bin's share of the forecasts.
    const double r = 2.0 + 6.0 * std::sqrt(static_cast<double>(bin.n) / std::max(1, c.forecasts));
    svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"#3b6ea5\"><title>{:.1f}-{:.1f}: {} "
                       "forecasts, mean {:.3f}, frequency {:.3f}</title></circle>\n",
                       X(bin.mean_p), Y(bin.frequency), r, bin.lo, bin.hi, bin.n, bin.mean_p, bin.frequency);
  }
  if (!pts.empty()) svg += "<polyline points=\"" + pts + "\" fill=\"none\" stroke=\"#3b6ea5\" stroke-width=\"1.5\"/>\n";
  svg += "</svg>\n";
  return svg;
}

}  // namespace clips::eval
