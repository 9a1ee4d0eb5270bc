#include "studies/scaling_test.hpp"

namespace clips::studies {
namespace scaling_test {
TEST(Scaling, AxesVaryOneQuantityEach) {
  const auto full = scaling_points(false);
  ASSERT_EQ(full.size(), 15u);
  std::vector<int> sides, goals, steps;
  for (const auto& p : full) {
    if (p.axis == "side") {
      sides.push_back(p.side);
      EXPECT_EQ(p.gems, 4);
    } else if (p.axis == "goals") {
      goals.push_back(p.gems);
      EXPECT_EQ(p.side, 20);
    } else {
      steps.push_back(p.steps);
      EXPECT_EQ(p.side, 20);
    }
  }
  EXPECT_EQ(sides, (std::vector<int>{9, 15, 20, 30, 40}));
  EXPECT_EQ(goals, (std::vector<int>{4, 8, 16, 32, 64}));
  EXPECT_EQ(steps, (std::vector<int>{10, 25, 50, 100, 200}));
  EXPECT_EQ(scaling_points(true).size(), 9u);
}

TEST(Scaling, CsvLineRoundTrips) {
  ScalingRow r = sample_row("goals", 16, 12.5);
  r.point.gems = 16;
  r.point.side = 20;
  r.budget_stops = 7;
  r.time_budget_hit = true;
  r.error = "a, b\nc";  // commas and newlines cannot break the line
  const std::string line = scaling_csv_line(r);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(count(line, ","), count(scaling_csv_header(), ","));
  const ScalingRow back = parse_scaling_csv_line(line);
  EXPECT_EQ(back.point.axis, "goals");
  EXPECT_EQ(back.point.value, 16);
  EXPECT_EQ(back.point.gems, 16);
  EXPECT_EQ(back.plans, 3);
  EXPECT_DOUBLE_EQ(back.belief_median_ms, 12.5);
  EXPECT_DOUBLE_EQ(back.belief_p95_ms, 50);
  EXPECT_DOUBLE_EQ(back.p_true_mean, 0.625);
  EXPECT_EQ(back.budget_stops, 7u);
  EXPECT_TRUE(back.time_budget_hit);
  EXPECT_EQ(back.error, "a; b c");
  EXPECT_THROW(parse_scaling_csv_line("side,9"), InputError);
  EXPECT_THROW(parse_scaling_csv_line(std::regex_replace(line, std::regex("^goals,16"), "goals,x")), InputError);
}

TEST(Scaling, QuantileIsNearestRank) {
  EXPECT_EQ(scaling_quantile({}, 0.5), 0);
  EXPECT_EQ(scaling_quantile({3, 1, 2}, 0.5), 2);
  std::vector<double> xs;
  for (int i = 1; i <= 100; ++i) xs.push_back(i);
  EXPECT_EQ(scaling_quantile(xs, 0.95), 95);
  EXPECT_EQ(scaling_quantile(xs, 1.0), 100);
}

TEST(Scaling, SvgHasThreePanelsAndAPointPerValue) {
  std::vector<ScalingRow> rows;
  for (int s : {9, 15, 20}) rows.push_back(sample_row("side", s, s * 1.0));
  for (int g : {4, 8}) rows.push_back(sample_row("goals", g, g * 2.0));
  ScalingRow failed = sample_row("steps", 10, 1);
  failed.plans = 0;  // a point without results is left out
  rows.push_back(failed);
  const std::string svg = scaling_svg(rows);
  ASSERT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(count(svg, "<svg"), 1);
  // Well-formed enough for a browser: every element opened is closed.
  EXPECT_EQ(count(svg, "<text"), count(svg, "</text>"));
  EXPECT_EQ(count(svg, "<circle"), count(svg, "</circle>"));
  EXPECT_EQ(count(svg, "<title>"), count(svg, "</title>"));
  // Four series (belief/decision x median/p95) at each of the 5 points.
  EXPECT_EQ(count(svg, "<circle"), 4 * 5);
  EXPECT_EQ(count(svg, "<path"), 4 * 2);  // two panels with data
  EXPECT_NE(svg.find("map side"), std::string::npos);
  EXPECT_NE(svg.find("candidate goals"), std::string::npos);
  EXPECT_NE(svg.find("no data"), std::string::npos);  // the steps panel
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(Scaling, SvgLeavesOutTimesThatWereNotMeasured) {
  std::vector<ScalingRow> rows;
  for (int t : {10, 25, 50}) rows.push_back(sample_row("steps", t, 5.0));
  // Past the horizon no assistance decision is made: its times read 0.
  rows.back().decisions = 0;
  rows.back().decision_median_ms = 0;
  rows.back().decision_p95_ms = 0;
  const std::string svg = scaling_svg(rows);
  EXPECT_EQ(count(svg, "<circle"), 4 * 3 - 2);  // no decision dots at 50 steps
  EXPECT_EQ(count(svg, "<path"), 4);
  EXPECT_EQ(svg.find("decision, median 0 ms"), std::string::npos);
}

}  // namespace scaling_test

}  // namespace clips::studies
