#include "app/scaling_cli.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "app/exit_codes.hpp"
#include "language/listener.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace fs = std::filesystem;

namespace {

studies::ScalingPoint find_point(const std::string& spec, bool quick) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw UsageError("--scaling-point " + spec + " is not AXIS:VALUE (e.g. goals:16)");
  const std::string axis = spec.substr(0, colon), value = spec.substr(colon + 1);
  for (bool q : {quick, !quick})
    for (const auto& p : studies::scaling_points(q))
      if (p.axis == axis && std::to_string(p.value) == value) return p;
  throw UsageError("--scaling-point " + spec + ": no such point (axes side, goals, steps; see --scaling)");
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw InputError("cannot write " + path.string());
}

std::string self_exe() {
  std::error_code ec;
  auto p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw InputError("cannot find the clips executable (/proc/self/exe): " + ec.message());
  return p.string();
}

}  // namespace

int run_scaling_cli(const ScalingCli& cli) {
  studies::ScalingSettings settings = cli.settings;
  if (settings.domain_file.empty()) settings.domain_file = util::data_path("domains/doors-keys-gems/domain.pddl");
  if (!cli.point.empty()) {
    const studies::ScalingPoint point = find_point(cli.point, cli.quick);
    auto lm = language::make_language_model(cli.lm_kind, {});
    const studies::ScalingRow row = studies::run_scaling_point(point, settings, *lm);
    fmt::print("{}\n", studies::scaling_csv_line(row));
    std::fflush(stdout);
    return row.error.empty() ? kExitOk : kExitSomeFailed;
  }

  std::error_code ec;
  fs::create_directories(cli.out, ec);
  if (ec) throw InputError("--out " + cli.out + ": " + ec.message());
  const std::string exe = self_exe();
  std::vector<studies::ScalingRow> rows;
  int failed = 0;
  const auto points = studies::scaling_points(cli.quick);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    // Every argument is a number or a fixed word, so no quoting is needed.
    const std::string cmd = fmt::format(
        "'{}' bench --scaling-point {}:{} --scaling-plans {} --seed {} --max-nodes {} --point-seconds {} --lm {}{}",
        exe, p.axis, p.value, settings.plans, settings.seed, settings.max_nodes, settings.point_seconds, cli.lm_kind,
        cli.quick ? " --quick" : "");
    fmt::print(stderr, "scaling: point {}/{}: {} = {} ...\n", i + 1, points.size(), p.axis, p.value);
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    if (!pipe) throw InputError("cannot start " + exe);
    std::string text;
    char buf[4096];
    while (size_t n = std::fread(buf, 1, sizeof buf, pipe.get())) text.append(buf, n);
    pipe.reset();
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const std::string line = text.substr(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
    studies::ScalingRow row;
    try {
      row = studies::parse_scaling_csv_line(line);
    } catch (const InputError&) {
      row.point = p;
      row.error = "the point's process printed no result";
    }
    if (!row.error.empty()) ++failed;
    fmt::print(stderr,
               "scaling: {} = {}: {} plans, belief step median {:.3g} ms (p95 {:.3g}), decision median {:.3g} ms "
               "(p95 {:.3g}), {:.0f} MB, P(g_true) {:.2f}, {} budget stops{}{}\n",
               p.axis, p.value, row.plans, row.belief_median_ms, row.belief_p95_ms, row.decision_median_ms,
               row.decision_p95_ms, row.max_rss_mb, row.p_true_mean, row.budget_stops,
               row.time_budget_hit ? ", stopped by --point-seconds" : "", row.error.empty() ? "" : "; " + row.error);
    rows.push_back(row);
    std::string csv = studies::scaling_csv_header() + "\n";
    for (const auto& r : rows) csv += studies::scaling_csv_line(r) + "\n";
    write_file(fs::path(cli.out) / "scaling.csv", csv);
    write_file(fs::path(cli.out) / "scaling.svg", studies::scaling_svg(rows));
  }
  fmt::print(stderr, "wrote {0}/scaling.csv and {0}/scaling.svg\n", cli.out);
  return failed == 0 ? kExitOk : kExitSomeFailed;
}

}  // namespace clips::app
