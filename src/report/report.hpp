#pragma once
// `clips bench --report DIR`: a self-contained HTML page (no scripts, no
// external resources) with the results table beside the paper's numbers,
// per-method metric charts (inline SVG) and one row per plan linking to its
// animated GIF (observed prefix + CLIPS assistance) and its goal-posterior-
// over-time plot (DIR/plans/<id>.gif, DIR/plans/<id>_posterior.svg).
#include <string>
#include <vector>

#include "eval/bench.hpp"
#include "render/scene.hpp"

namespace clips::report {

struct ReportOptions {
  std::string dir;
  std::string paper_json;   // data/paper/results.json
  bool render_gifs = true;  // false: the page and the SVG plots only
  int jobs = 0;             // GIF rendering threads; 0: all cores
  int cell_px = 32;
};

struct PlanAssets {
  std::string gif;       // relative to the report dir, "" when none
  std::string svg;       // relative path of the posterior plot, "" when none
  std::string svg_text;  // the same plot, inlined into the page
  std::string error;     // why the pictures are missing
  std::string utterance;
};

// Writes DIR/report.html and DIR/plans/*; returns the page's path. Throws
// InputError when DIR cannot be written.
std::string write_report(const eval::BenchReport& report, const ReportOptions& options);

// The pieces, exposed for tests.
std::string report_html(const eval::BenchReport& report, const std::string& paper_json_path,
                        const std::vector<PlanAssets>& assets);  // assets: one per report.plans entry (or empty)
// Goal posterior over observed steps: one line per goal; `colours` are CSS colours.
std::string posterior_svg(const std::vector<std::string>& goals, const std::vector<std::string>& colours,
                          const std::vector<std::vector<double>>& steps, int true_goal,
                          const std::vector<int>& utterance_steps, int width = 360, int height = 180);
std::string html_escape(const std::string& text);

}  // namespace clips::report
