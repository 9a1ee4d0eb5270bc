#include "report/report_test.hpp"

namespace clips::report {
namespace report_test {
// The latency figures' quantiles: the value at rank floor(q (n - 1)).
TEST(BenchLatency, QuantilesAreTheBenchmarksRanks) {
  const eval::LatencyStats l = eval::LatencyStats::of({5, 1, 4, 2, 3, 10, 6, 7, 8, 9, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21});
  EXPECT_EQ(l.n, 21u);
  EXPECT_EQ(l.median, 11);
  EXPECT_EQ(l.p95, 20);
  EXPECT_EQ(l.max, 21);
  EXPECT_EQ(eval::LatencyStats::of({}).n, 0u);
}

TEST(ReportHtml, EscapesAndPosteriorSvg) {
  EXPECT_EQ(html_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
  auto svg = posterior_svg({"gem1", "gem2"}, {"#ff0000", "#00ff00"}, {{0.5, 0.5}, {0.8, 0.2}, {0.9, 0.1}}, 0, {1});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("polyline"), std::string::npos);
  EXPECT_NE(svg.find("gem1 (true)"), std::string::npos);
  EXPECT_NE(svg.find("utterance"), std::string::npos);
}

}  // namespace report_test

}  // namespace clips::report
