#include "report/report.hpp"

#include "eval/breakdown.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "scenes/scenes.hpp"
#include "render/theme.hpp"
#include "util/error.hpp"

namespace clips::report {

namespace fs = std::filesystem;

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

std::string hex(render::Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

// Distinct line colours for goals without a colour of their own.
const std::vector<std::string> kPalette = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#b07aa1",
                                           "#76b7b2", "#edc948", "#9c755f", "#ff9da7", "#bab0ac"};

std::string css_colour(const std::string& name, size_t index) {
  if (name.empty()) return kPalette[index % kPalette.size()];
  return hex(render::named_colour(name));
}

struct Column {
  std::string key, label;
  bool unit_range;  // [0, 1] scale
};
const std::vector<Column> kColumns = {{"p_true_goal", "P(true goal)", true},
                                      {"assist_precision", "Assist. precision", true},
                                      {"assist_recall", "Assist. recall", true},
                                      {"rel_plan_length", "Rel. plan length", false},
                                      {"rel_human_cost", "Rel. human cost", false}};

const nlohmann::json* paper_value(const nlohmann::json* paper, const std::string& method, const std::string& key) {
  if (!paper || !paper->contains(method) || !(*paper)[method].contains(key)) return nullptr;
  const auto& v = (*paper)[method][key];
  if (!v.is_array() || v.size() < 2) return nullptr;
  return &v;
}

// One horizontal bar chart for a metric: our mean with a standard-error
// whisker, the paper's mean as a black diamond.
std::string metric_svg(const Column& col, const eval::BenchReport& r, const nlohmann::json* paper) {
  struct Row {
    std::string method;
    const eval::MeanSe* ours;
    const nlohmann::json* theirs;
  };
  std::vector<Row> rows;
  double hi = col.unit_range ? 1.0 : 0.0;
  for (auto& s : r.summary) {
    auto it = s.metrics.find(col.key);
    const eval::MeanSe* ours = it == s.metrics.end() ? nullptr : &it->second;
    const nlohmann::json* theirs = paper_value(paper, s.method, col.key);
    if (!ours && !theirs) continue;
    rows.push_back({s.method, ours, theirs});
    if (ours) hi = std::max(hi, ours->mean + ours->se);
    if (theirs) hi = std::max(hi, (*theirs)[0].get<double>() + (*theirs)[1].get<double>());
  }
  double tick = 0.25;
  if (!col.unit_range) {
    if (!std::isfinite(hi)) hi = 1;
    tick = hi <= 2 ? 0.5 : 1.0;
    // Past 10, a 1-2-5 step that keeps the axis to about ten ticks.
    if (hi > 10) {
      const double step = std::pow(10.0, std::floor(std::log10(hi / 10)));
      tick = hi / step <= 20 ? 2 * step : hi / step <= 50 ? 5 * step : 10 * step;
    }
    hi = std::max(1.0, std::ceil(hi / tick) * tick);
  }
  const int label_w = 150, plot_w = 230, row_h = 22, top = 26, bottom = 22;
  const int w = label_w + plot_w + 20, h = top + static_cast<int>(rows.size()) * row_h + bottom;
  auto X = [&](double v) { return label_w + plot_w * std::clamp(v / hi, 0.0, 1.0); };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" role=\"img\" "
      "aria-label=\"{}\">\n",
      w, h, w, h, html_escape(col.label));
  svg += fmt::format("<text x=\"{}\" y=\"16\" class=\"ct\">{}</text>\n", 4, html_escape(col.label));
  for (int k = 0; k * tick <= hi + 1e-9; ++k) {
    double v = k * tick;
    double x = X(v);
    svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{}\" stroke=\"#e3e0d8\"/>\n", x, top - 4, x,
                       h - bottom + 2);
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" class=\"ax\" text-anchor=\"middle\">{:.2g}</text>\n", x,
                       h - bottom + 15, v);
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    int y = top + static_cast<int>(i) * row_h;
    svg += fmt::format("<text x=\"{}\" y=\"{}\" class=\"lb\" text-anchor=\"end\">{}</text>\n", label_w - 6, y + 15,
                       html_escape(rows[i].method));
    if (rows[i].ours) {
      const eval::MeanSe& m = *rows[i].ours;
      svg += fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{:.1f}\" height=\"{}\" fill=\"{}\"><title>ours {:.3f} (se {:.3f})</title></rect>\n",
          label_w, y + 4, X(m.mean) - label_w, row_h - 8, rows[i].method == "clips" ? "#4e79a7" : "#9fb8d3", m.mean,
          m.se);
      if (m.se > 0)
        svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{}\" stroke=\"#222\" stroke-width=\"1.5\"/>\n",
                           X(m.mean - m.se), y + row_h / 2, X(m.mean + m.se), y + row_h / 2);
    }
    if (rows[i].theirs) {
      double v = (*rows[i].theirs)[0].get<double>();
      double x = X(v), cy = y + row_h / 2.0;
      svg += fmt::format(
          "<path d=\"M{:.1f} {:.1f} l5 5 l-5 5 l-5 -5 z\" fill=\"#222\"><title>paper {:.2f}</title></path>\n", x,
          cy - 5, v);
    }
  }
  svg += "</svg>\n";
  return svg;
}

std::string cell(const eval::MeanSe* m) {
  if (!m) return "<td class=\"na\">\u2013</td>";
  return fmt::format("<td>{:.2f} <span class=\"se\">({:.2f})</span></td>", m->mean, m->se);
}

std::string paper_cell(const nlohmann::json* v) {
  if (!v) return "<td class=\"paper na\">\u2013</td>";
  return fmt::format("<td class=\"paper\">{:.2f} <span class=\"se\">({:.2f})</span></td>", (*v)[0].get<double>(),
                     (*v)[1].get<double>());
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; color: #212128; background: #fbfaf7;
       margin: 24px; font-size: 14px; }
h1 { font-size: 22px; margin: 0 0 6px 0; } h2 { font-size: 17px; margin: 26px 0 8px 0; }
.meta { color: #666; margin-bottom: 12px; }
table { border-collapse: collapse; background: #fff; }
th, td { border: 1px solid #ddd8cc; padding: 4px 8px; text-align: center; vertical-align: middle; }
th { background: #f1ede3; }
td.m { text-align: left; font-family: "DejaVu Sans Mono", monospace; }
td.paper { background: #f7f5ef; color: #444; }
.se { color: #888; font-size: 12px; }
.na { color: #aaa; }
.skipped td { color: #8a6d3b; background: #fcf8e3; text-align: left; }
.charts { display: flex; flex-wrap: wrap; gap: 12px; }
.charts svg { background: #fff; border: 1px solid #ddd8cc; }
svg .ct { font-size: 13px; font-weight: bold; fill: #212128; }
svg .lb { font-size: 11px; fill: #333; font-family: "DejaVu Sans Mono", monospace; }
svg .ax { font-size: 10px; fill: #777; }
td.utt { max-width: 260px; text-align: left; font-style: italic; }
td.err { color: #a33; text-align: left; max-width: 320px; }
img.anim { max-width: 240px; max-height: 240px; border: 1px solid #ddd8cc; }
.legend span { display: inline-block; margin-right: 10px; }
.sw { display: inline-block; width: 12px; height: 12px; vertical-align: -2px; margin-right: 3px; }
)";

}  // namespace

std::string posterior_svg(const std::vector<std::string>& goals, const std::vector<std::string>& colours,
                          const std::vector<std::vector<double>>& steps, int true_goal,
                          const std::vector<int>& utterance_steps, int width, int height) {
  const int left = 34, right = 10, top = 10, bottom = 36;
  const double pw = width - left - right, ph = height - top - bottom;
  const int T = std::max<int>(1, static_cast<int>(steps.size()) - 1);
  auto X = [&](double t) { return left + pw * t / T; };
  auto Y = [&](double p) { return top + ph * (1 - std::clamp(p, 0.0, 1.0)); };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" role=\"img\" "
      "aria-label=\"goal posterior over time\">\n<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>\n",
      width, height, width, height, width, height);
  for (double p : {0.0, 0.5, 1.0}) {
    svg += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#e3e0d8\"/>\n", left, Y(p),
                       left + pw, Y(p));
    svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#777\" text-anchor=\"end\">{:g}</text>\n",
                       left - 4, Y(p) + 3, p);
  }
  for (int u : utterance_steps) {
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>"
        "<text x=\"{0:.1f}\" y=\"{3}\" font-size=\"10\" fill=\"#555\" text-anchor=\"{4}\">utterance</text>\n",
        X(u), top, top + ph, top + 8, X(u) > width - 40 ? "end" : X(u) < left + 30 ? "start" : "middle");
  }
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"10\" fill=\"#777\" text-anchor=\"middle\">step (0..{})</text>\n",
                     left + pw / 2, height - bottom + 13, static_cast<int>(steps.size()) - 1);
  for (size_t g = 0; g < goals.size(); ++g) {
    std::string pts;
    for (size_t t = 0; t < steps.size(); ++t)
      pts += fmt::format("{:.1f},{:.1f} ", X(static_cast<double>(t)), Y(g < steps[t].size() ? steps[t][g] : 0));
    const bool truth = static_cast<int>(g) == true_goal;
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{}/>\n", pts,
                       g < colours.size() ? colours[g] : "#444", truth ? 3 : 1.6,
                       truth ? "" : " stroke-opacity=\"0.85\"");
  }
  // Legend along the bottom.
  double lx = left;
  for (size_t g = 0; g < goals.size(); ++g) {
    svg += fmt::format("<rect x=\"{:.1f}\" y=\"{}\" width=\"10\" height=\"10\" fill=\"{}\"/>", lx, height - 14,
                       g < colours.size() ? colours[g] : "#444");
    std::string label = goals[g] + (static_cast<int>(g) == true_goal ? " (true)" : "");
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"10\" fill=\"#333\">{}</text>\n", lx + 13, height - 5,
                       html_escape(label));
    lx += 20 + 6.2 * static_cast<double>(label.size());
  }
  svg += "</svg>\n";
  return svg;
}

std::string report_html(const eval::BenchReport& r, const std::string& paper_json_path, const std::vector<PlanAssets>& assets) {
  nlohmann::json paper_all;
  if (std::ifstream in(paper_json_path); in) {
    try {
      paper_all = nlohmann::json::parse(in);
    } catch (...) {
    }
  }
  // Only the paper's own datasets are shown beside its numbers.
  const nlohmann::json* paper = eval::paper_results_for(r, paper_all);
  const size_t per_metric = paper ? 2 : 1;

  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<title>CLIPS bench report \u2014 " + html_escape(r.domain) + "</title>\n<style>" + std::string(kStyle) +
       "</style>\n</head>\n<body>\n";
  h += "<h1>CLIPS bench report: " + html_escape(r.domain) + "</h1>\n";
  h += fmt::format("<div class=\"meta\">dataset <code>{}</code> \u00b7 {} plans ({} failed) \u00b7 LM {} \u00b7 "
                   "{:.1f} s wall \u00b7 max RSS {:.0f} MiB</div>\n",
                   html_escape(r.dataset), r.plans.size(), r.failed_plans, html_escape(r.lm), r.wall_seconds,
                   r.max_rss_kb / 1024.0);
  if (const std::string note = eval::partial_note(r); !note.empty())
    h += "<div class=\"meta\"><b>" + html_escape(note) + "</b></div>\n";

  // ---- results table
  h += std::string("<h2>Results (mean, standard error in brackets)") + (paper ? ", ours beside the paper's" : "") +
       "</h2>\n<table class=\"results\">\n<tr><th rowspan=\"2\">method</th>";
  for (auto& c : kColumns) h += fmt::format("<th colspan=\"{}\">", per_metric) + html_escape(c.label) + "</th>";
  h += "</tr>\n<tr>";
  for (size_t i = 0; i < kColumns.size(); ++i) h += paper ? "<th>ours</th><th>paper</th>" : "<th>ours</th>";
  h += "</tr>\n";
  bool multimodal_ran = false;
  for (auto& s : r.summary) {
    multimodal_ran |= s.method == "multimodal";
    h += "<tr><td class=\"m\">" + html_escape(s.method) + "</td>";
    for (auto& c : kColumns) {
      auto it = s.metrics.find(c.key);
      h += cell(it == s.metrics.end() ? nullptr : &it->second);
      if (paper) h += paper_cell(paper_value(paper, s.method, c.key));
    }
    h += "</tr>\n";
  }
  if (eval::paper_has_method(paper_all, r.domain, "multimodal") && !multimodal_ran) {
    h += fmt::format("<tr class=\"skipped\"><td class=\"m\">multimodal</td><td colspan=\"{}\">skipped: no chat endpoint "
                     "configured (--chat-base-url or $CLIPS_CHAT_BASE_URL)</td></tr>\n",
                     kColumns.size() * per_metric);
  }
  h += "</table>\n";

  // ---- charts
  h += "<h2>Metrics by method</h2>\n<p class=\"meta\">Bars: ours with a standard-error whisker; "
       "\u25c6: the paper's mean.</p>\n<div class=\"charts\">\n";
  for (auto& c : kColumns) h += metric_svg(c, r, paper);
  h += "</div>\n";

  // ---- splits, instruction categories, calibration
  if (const eval::Breakdown b = eval::breakdown(r); !b.empty()) {
    if (!b.splits.empty() || !b.categories.empty())
      h += "<h2>By split and by instruction category</h2>\n<pre class=\"breakdown\">" +
           html_escape(eval::breakdown_table(eval::Breakdown{b.splits, b.categories, {}})) + "</pre>\n";
    if (!b.calibration.empty()) {
      h += "<h2>Calibration of the goal posterior after the instruction</h2>\n<p class=\"meta\">Every candidate "
           "goal of every plan is one forecast: its posterior probability after the instruction against whether it "
           "was the true goal, in ten bins. Dashed: perfect calibration; dot size: the bin's share of the "
           "forecasts.</p>\n<div class=\"charts\">\n";
      for (const auto& c : b.calibration) h += eval::reliability_svg(c);
      h += "</div>\n";
    }
  }

  // ---- per-plan rows
  h += "<h2>Plans</h2>\n<table class=\"plans\">\n<tr><th>plan</th><th>utterance / true goal</th><th>P(true goal)<br>CLIPS"
       "</th><th>precision / recall<br>CLIPS</th><th>run (observed + CLIPS assistance)</th><th>goal posterior over "
       "observed steps</th></tr>\n";
  for (size_t i = 0; i < r.plans.size(); ++i) {
    const eval::PlanOutcome& p = r.plans[i];
    const PlanAssets* a = i < assets.size() ? &assets[i] : nullptr;
    h += "<tr id=\"plan-" + html_escape(p.plan_id) + "\"><td class=\"m\">" + html_escape(p.plan_id) + "</td>";
    if (!p.error.empty()) {
      h += "<td class=\"err\" colspan=\"5\">failed: " + html_escape(p.error) + "</td></tr>\n";
      continue;
    }
    std::string truth = p.true_goal >= 0 && p.true_goal < static_cast<int>(p.goals.size()) ? p.goals[p.true_goal] : "?";
    h += "<td class=\"utt\">";
    if (a && !a->utterance.empty()) h += "\u201c" + html_escape(a->utterance) + "\u201d<br>";
    h += "true goal: <b>" + html_escape(truth) + "</b></td>";
    const eval::MethodResult* c = p.find("clips");
    if (c && c->error.empty()) {
      h += c->p_true_goal ? fmt::format("<td>{:.2f}</td>", *c->p_true_goal) : "<td class=\"na\">\u2013</td>";
      h += fmt::format("<td>{:.2f} / {:.2f}</td>", c->precision, c->recall);
    } else {
      h += "<td class=\"na\">\u2013</td><td class=\"na\">\u2013</td>";
    }
    if (a && !a->gif.empty())
      h += "<td><a href=\"" + html_escape(a->gif) + "\"><img class=\"anim\" src=\"" + html_escape(a->gif) +
           "\" alt=\"animation of plan " + html_escape(p.plan_id) + "\"></a></td>";
    else
      h += "<td class=\"na\">" + html_escape(a && !a->error.empty() ? a->error : "not rendered") + "</td>";
    if (a && !a->svg_text.empty())
      h += "<td>" + a->svg_text + (a->svg.empty() ? "" : "<br><a href=\"" + html_escape(a->svg) + "\">" +
                                                            html_escape(a->svg) + "</a>") + "</td>";
    else
      h += "<td class=\"na\">\u2013</td>";
    h += "</tr>\n";
  }
  h += "</table>\n</body>\n</html>\n";
  return h;
}

std::string write_report(const eval::BenchReport& r, const ReportOptions& o) {
  std::error_code ec;
  fs::create_directories(fs::path(o.dir) / "plans", ec);
  if (ec) throw InputError("cannot create report directory " + o.dir + "/plans: " + ec.message());
  std::vector<PlanAssets> assets(r.plans.size());
  std::atomic<size_t> next{0};
  // One dataset for every worker: the bench's own when it ran here, else loaded once.
  std::shared_ptr<const data::Dataset> ds = r.loaded;
  std::string load_error;
  if (!ds) try {
      ds = std::make_shared<const data::Dataset>(data::Dataset::load(r.dataset));
    } catch (const std::exception& e) {
      load_error = e.what();
    }
  auto worker = [&] {
    for (;;) {
      size_t i = next++;
      if (i >= r.plans.size()) return;
      const eval::PlanOutcome& p = r.plans[i];
      PlanAssets& a = assets[i];
      if (!p.error.empty()) continue;
      try {
        if (!ds) throw InputError(load_error);
        const auto& rec = ds->plan(p.plan_id);
        auto task = ds->task(rec.problem_id);
        std::vector<std::string> colours;
        for (size_t g = 0; g < p.goals.size(); ++g)
          colours.push_back(css_colour(scenes::goal_colour(*task, ds->pack(), p.goals[g]), g));
        std::vector<int> utt;
        for (auto& u : rec.observed.utterances) {
          utt.push_back(u.index);
          a.utterance += (a.utterance.empty() ? "" : " ") + u.text;
        }
        a.svg_text = posterior_svg(p.goals, colours, p.goal_posterior_steps, p.true_goal, utt);
        a.svg = "plans/" + p.plan_id + "_posterior.svg";
        std::ofstream(fs::path(o.dir) / a.svg) << a.svg_text;
        if (o.render_gifs && ds->pack().spec().scene != domains::SceneKind::Text) {
          scenes::PlanRun run;
          run.goals = p.goals;
          run.observed_posterior = p.goal_posterior_steps;
          if (const eval::MethodResult* c = p.find("clips"); c && c->error.empty()) {
            run.final_posterior = c->goal_posterior;
            run.assisted = c->plan;
            run.label = "CLIPS";
          }
          auto frames = scenes::plan_frames(*ds, rec, run);
          render::RenderOptions ro;
          ro.cell_px = o.cell_px;
          std::string rel = "plans/" + p.plan_id + ".gif";
          scenes::write_plan_gif(frames, (fs::path(o.dir) / rel).string(), ro);
          a.gif = rel;
        }
      } catch (const std::exception& e) {
        a.error = e.what();
      }
    }
  };
  int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(r.plans.size())));
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  std::string path = (fs::path(o.dir) / "report.html").string();
  std::ofstream out(path);
  if (!(out << report_html(r, o.paper_json, assets))) throw InputError("cannot write " + path);
  return path;
}

}  // namespace clips::report
