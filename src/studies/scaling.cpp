#include "studies/scaling.hpp"

#include <fmt/core.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "data/dataset.hpp"
#include "eval/experiment.hpp"
#include "generate/generate.hpp"
#include "util/error.hpp"

namespace clips::studies {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The observed prefix of `p` made T actions long: the first T of the whole
// joint sequence (at most all but its last action, the goal's pick-up).
data::PlanRecord with_prefix(const data::PlanRecord& p, int steps) {
  std::vector<pddl::PlanLine> all = p.observed.actions;
  all.insert(all.end(), p.completed.actions.begin(), p.completed.actions.end());
  const size_t k = std::min(static_cast<size_t>(steps), all.size() - 1);
  data::PlanRecord out = p;
  out.observed.actions.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k));
  out.completed.actions.assign(all.begin() + static_cast<std::ptrdiff_t>(k), all.end());
  for (auto& u : out.observed.utterances) u.index = std::min(u.index, static_cast<int>(k));
  return out;
}

double rss_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<double>(ru.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

}  // namespace

double scaling_quantile(std::vector<double> xs, double q) {
  if (xs.empty()) return 0;
  std::sort(xs.begin(), xs.end());
  const double pos = std::ceil(q * static_cast<double>(xs.size())) - 1;
  return xs[static_cast<size_t>(std::clamp(pos, 0.0, static_cast<double>(xs.size() - 1)))];
}

std::vector<ScalingPoint> scaling_points(bool quick) {
  std::vector<ScalingPoint> out;
  const std::vector<int> sides = quick ? std::vector<int>{9, 15, 20} : std::vector<int>{9, 15, 20, 30, 40};
  const std::vector<int> goals = quick ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 32, 64};
  const std::vector<int> steps = quick ? std::vector<int>{10, 25, 50} : std::vector<int>{10, 25, 50, 100, 200};
  for (int s : sides) {
    ScalingPoint p;
    p.axis = "side";
    p.value = p.side = s;
    p.max_steps = std::max(100, 10 * s);  // walks across big maps are long
    out.push_back(p);
  }
  for (int g : goals) {
    // 64 gems (70 objects) need more floor than 11x11 has: the whole axis
    // runs on 20x20 maps.
    ScalingPoint p;
    p.axis = "goals";
    p.value = p.gems = g;
    p.side = 20;
    p.max_steps = 200;
    out.push_back(p);
  }
  for (int t : steps) {
    // Long sequences: 20x20 maps, a noisy human (T = 2), up to 400 actions.
    ScalingPoint p;
    p.axis = "steps";
    p.value = p.steps = t;
    p.side = 20;
    p.temperature = 2;
    p.max_steps = 400;
    out.push_back(p);
  }
  return out;
}

ScalingRow run_scaling_point(const ScalingPoint& point, const ScalingSettings& settings, lm::LanguageModel& lm) {
  ScalingRow row;
  row.point = point;
  const auto t0 = Clock::now();
  fs::path dir;
  try {
    generate::GenerateOptions g;
    g.domain_file = settings.domain_file;
    g.map.width = g.map.height = point.side;
    g.map.counts = {{"gem", point.gems}, {"key", point.keys}, {"door", point.doors}};
    g.problems = settings.plans;
    g.plans_per_problem = 1;
    g.seed = settings.seed;
    g.temperature = point.temperature;
    g.max_steps = point.max_steps;
    g.refine_nodes = settings.max_nodes;  // drawn from the model inference below assumes
    const generate::GeneratedDataset ds_files = generate::generate_dataset(g, &lm);
    dir = fs::temp_directory_path() / fmt::format("clips-scaling-{}-{}-{}", ::getpid(), point.axis, point.value);
    generate::write_dataset(ds_files, dir.string(), true);
    row.generate_seconds = since(t0);

    const auto t1 = Clock::now();
    const data::Dataset ds = data::Dataset::load(dir.string());
    std::vector<double> belief, decisions, observed;
    double p_true = 0;
    eval::ExperimentOptions o;
    o.methods = {"clips"};
    o.refine_max_nodes = settings.max_nodes;
    std::vector<double> step_seconds;
    size_t stops = 0;
    o.on_inference = [&](const inference::InferenceRun& run) {
      for (size_t t = 1; t < run.steps.size(); ++t) step_seconds.push_back(run.steps[t].seconds);
      stops += run.searches_stopped_by_budget;
    };
    for (const auto& plan : ds.plans()) {
      if (row.plans > 0 && since(t1) > settings.point_seconds) {
        row.time_budget_hit = true;
        break;
      }
      const data::PlanRecord p = point.steps > 0 ? with_prefix(plan, point.steps) : plan;
      step_seconds.clear();
      const eval::PlanOutcome out = eval::evaluate_plan(ds, p, lm, o);
      const eval::MethodResult* r = out.find("clips");
      if (!out.error.empty() || !r || !r->error.empty() || !r->p_true_goal) {
        ++row.plans_failed;
        if (row.error.empty()) row.error = !out.error.empty() ? out.error : r ? r->error : "no clips result";
        continue;
      }
      ++row.plans;
      belief.insert(belief.end(), step_seconds.begin(), step_seconds.end());
      decisions.insert(decisions.end(), r->decision_seconds.begin(), r->decision_seconds.end());
      observed.push_back(static_cast<double>(p.observed.actions.size()));
      p_true += *r->p_true_goal;
    }
    row.run_seconds = since(t1);
    row.budget_stops = stops;
    row.belief_steps = static_cast<int>(belief.size());
    row.decisions = static_cast<int>(decisions.size());
    row.belief_median_ms = scaling_quantile(belief, 0.5) * 1e3;
    row.belief_p95_ms = scaling_quantile(belief, 0.95) * 1e3;
    row.decision_median_ms = scaling_quantile(decisions, 0.5) * 1e3;
    row.decision_p95_ms = scaling_quantile(decisions, 0.95) * 1e3;
    if (row.plans > 0) {
      p_true /= row.plans;
      row.p_true_mean = p_true;
      double sum = 0;
      for (double v : observed) sum += v;
      row.observed_steps_mean = sum / static_cast<double>(observed.size());
    }
    if (row.plans > 0) row.error.clear();  // a point with results keeps them; failures are counted
  } catch (const std::exception& e) {
    row.error = e.what();
  }
  std::error_code ec;
  if (!dir.empty()) fs::remove_all(dir, ec);
  row.max_rss_mb = rss_mb();
  return row;
}

// ------------------------------------------------------------------ CSV

std::string scaling_csv_header() {
  return "axis,value,side,gems,keys,doors,steps,plans,plans_failed,observed_steps_mean,belief_steps,"
         "belief_median_ms,belief_p95_ms,decisions,decision_median_ms,decision_p95_ms,max_rss_mb,p_true_mean,"
         "budget_stops,time_budget_hit,generate_seconds,run_seconds,error";
}

std::string scaling_csv_line(const ScalingRow& r) {
  std::string err = r.error;
  std::replace(err.begin(), err.end(), ',', ';');
  std::replace(err.begin(), err.end(), '\n', ' ');
  std::replace(err.begin(), err.end(), '"', '\'');
  const ScalingPoint& p = r.point;
  return fmt::format("{},{},{},{},{},{},{},{},{},{:.1f},{},{:.4g},{:.4g},{},{:.4g},{:.4g},{:.1f},{:.4f},{},{},{:.1f},{:.1f},{}",
                     p.axis, p.value, p.side, p.gems, p.keys, p.doors, p.steps, r.plans, r.plans_failed,
                     r.observed_steps_mean, r.belief_steps, r.belief_median_ms, r.belief_p95_ms, r.decisions,
                     r.decision_median_ms, r.decision_p95_ms, r.max_rss_mb, r.p_true_mean, r.budget_stops,
                     r.time_budget_hit ? 1 : 0, r.generate_seconds, r.run_seconds, err);
}

ScalingRow parse_scaling_csv_line(const std::string& line) {
  std::vector<std::string> f;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) f.push_back(cell);
  if (!line.empty() && line.back() == ',') f.push_back("");
  if (f.size() != 23) throw InputError(fmt::format("not a scaling CSV line ({} fields, 23 expected): {}", f.size(), line));
  try {
    ScalingRow r;
    ScalingPoint& p = r.point;
    size_t i = 0;
    p.axis = f[i++];
    p.value = std::stoi(f[i++]);
    p.side = std::stoi(f[i++]);
    p.gems = std::stoi(f[i++]);
    p.keys = std::stoi(f[i++]);
    p.doors = std::stoi(f[i++]);
    p.steps = std::stoi(f[i++]);
    r.plans = std::stoi(f[i++]);
    r.plans_failed = std::stoi(f[i++]);
    r.observed_steps_mean = std::stod(f[i++]);
    r.belief_steps = std::stoi(f[i++]);
    r.belief_median_ms = std::stod(f[i++]);
    r.belief_p95_ms = std::stod(f[i++]);
    r.decisions = std::stoi(f[i++]);
    r.decision_median_ms = std::stod(f[i++]);
    r.decision_p95_ms = std::stod(f[i++]);
    r.max_rss_mb = std::stod(f[i++]);
    r.p_true_mean = std::stod(f[i++]);
    r.budget_stops = std::stoul(f[i++]);
    r.time_budget_hit = f[i++] == "1";
    r.generate_seconds = std::stod(f[i++]);
    r.run_seconds = std::stod(f[i++]);
    r.error = f[i++];
    return r;
  } catch (const std::logic_error&) {
    throw InputError("not a scaling CSV line (a number field does not parse): " + line);
  }
}

// ------------------------------------------------------------------ SVG

std::string scaling_svg(const std::vector<ScalingRow>& rows) {
  const std::vector<std::pair<std::string, std::string>> axes = {
      {"side", "map side (cells)"}, {"goals", "candidate goals (gems)"}, {"steps", "observed steps"}};
  struct Series {
    const char* name;
    const char* color;
    bool dashed;
    double ScalingRow::*field;
  };
  const Series series[] = {{"belief step, median", "#4e79a7", false, &ScalingRow::belief_median_ms},
                           {"belief step, p95", "#4e79a7", true, &ScalingRow::belief_p95_ms},
                           {"decision, median", "#e15759", false, &ScalingRow::decision_median_ms},
                           {"decision, p95", "#e15759", true, &ScalingRow::decision_p95_ms}};
  // One log scale for all panels, from the smallest to the largest time.
  double lo = 1e300, hi = 0;
  for (const auto& r : rows)
    for (const auto& s : series)
      if (r.plans > 0 && r.*s.field > 0) lo = std::min(lo, r.*s.field), hi = std::max(hi, r.*s.field);
  if (hi <= 0) lo = 0.1, hi = 1;
  const double dlo = std::floor(std::log10(lo)), dhi = std::max(dlo + 1, std::ceil(std::log10(hi)));
  const int pw = 230, ph = 190, left = 72, gap = 34, top = 34, bottom = 44, legend = 24;
  const int w = left + 3 * pw + 2 * gap + 16, h = top + ph + bottom + legend;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" role=\"img\" "
      "aria-label=\"CLIPS scaling: time per belief step and per assistance decision\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n"
      "<rect width=\"{}\" height=\"{}\" fill=\"#fff\"/>\n",
      w, h, w, h, w, h);
  auto Y = [&](double ms) {
    const double v = std::clamp(std::log10(std::max(ms, 1e-300)), dlo, dhi);
    return top + ph * (1 - (v - dlo) / (dhi - dlo));
  };
  for (size_t a = 0; a < axes.size(); ++a) {
    const int x0 = left + static_cast<int>(a) * (pw + gap);
    std::vector<const ScalingRow*> pts;
    for (const auto& r : rows)
      if (r.point.axis == axes[a].first && r.plans > 0) pts.push_back(&r);
    std::sort(pts.begin(), pts.end(), [](auto* x, auto* y) { return x->point.value < y->point.value; });
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>\n", x0 + pw / 2,
                       top - 12, axes[a].second);
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#999\"/>\n", x0, top,
                       pw, ph);
    for (int d = static_cast<int>(dlo); d <= static_cast<int>(dhi); ++d) {
      const double y = Y(std::pow(10.0, d));
      svg += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#e3e0d8\"/>\n", x0, y, x0 + pw, y);
      if (a == 0)
        svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{:g} ms</text>\n", x0 - 4, y + 4,
                           std::pow(10.0, d));
    }
    if (pts.empty()) {
      svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"#999\">no data</text>\n", x0 + pw / 2,
                         top + ph / 2);
      continue;
    }
    // x: log scale over the axis's values (they roughly double).
    const double xlo = std::log(static_cast<double>(pts.front()->point.value));
    const double xhi = std::log(static_cast<double>(pts.back()->point.value));
    auto X = [&](int v) {
      return xhi > xlo ? x0 + 14 + (pw - 28) * (std::log(static_cast<double>(v)) - xlo) / (xhi - xlo) : x0 + pw / 2.0;
    };
    for (const auto* r : pts)
      svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", X(r->point.value),
                         top + ph + 14, r->point.value);
    for (const auto& s : series) {
      // A time of 0 means the point has no such measurement (e.g. no
      // assistance decision after the horizon): no dot, and the line breaks.
      std::string d;
      bool pen_down = false;
      for (const auto* r : pts) {
        if (!(r->*s.field > 0)) {
          pen_down = false;
          continue;
        }
        d += fmt::format("{}{:.1f} {:.1f}", pen_down ? " L" : (d.empty() ? "M" : " M"), X(r->point.value), Y(r->*s.field));
        pen_down = true;
      }
      if (!d.empty())
        svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.8\"{}/>\n", d, s.color,
                           s.dashed ? " stroke-dasharray=\"4 3\"" : "");
      for (const auto* r : pts)
        if (r->*s.field > 0)
          svg += fmt::format(
            "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"2.5\" fill=\"{}\"><title>{} = {}: {} {:.3g} ms</title></circle>\n",
            X(r->point.value), Y(r->*s.field), s.color, axes[a].first, r->point.value, s.name, r->*s.field);
    }
  }
  // Legend.
  int lx = left;
  const int ly = top + ph + 34;
  for (const auto& s : series) {
    svg += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"1.8\"{}/>\n", lx,
                       ly, lx + 22, ly, s.color, s.dashed ? " stroke-dasharray=\"4 3\"" : "");
    svg += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", lx + 26, ly + 4, s.name);
    lx += 160;
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace clips::studies
