#include "studies/scaling_test.hpp"

namespace clips::studies {
namespace scaling_test {
TEST(ScalingRun, TinyPointRunsEndToEnd) {
  ScalingPoint p;
  p.axis = "side";
  p.value = p.side = 7;
  p.gems = 2;
  p.keys = 1;
  p.doors = 1;
  ScalingSettings s;
  s.plans = 1;
  s.domain_file = paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl";
  auto lm = language::make_language_model("embedded", {});
  const ScalingRow r = run_scaling_point(p, s, *lm);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.plans, 1);
  EXPECT_GT(r.belief_steps, 0);
  EXPECT_EQ(r.belief_steps, static_cast<int>(r.observed_steps_mean));
  EXPECT_GT(r.belief_median_ms, 0);
  EXPECT_GE(r.belief_p95_ms, r.belief_median_ms);
  EXPECT_GT(r.max_rss_mb, 1);
  EXPECT_GT(r.p_true_mean, 0);
  EXPECT_LE(r.p_true_mean, 1);
  const ScalingRow back = parse_scaling_csv_line(scaling_csv_line(r));
  EXPECT_EQ(back.plans, 1);
  const std::string svg = scaling_svg({r});
  EXPECT_EQ(count(svg, "<circle"), 4);

  // The steps axis moves actions of the completion into the observed prefix.
  ScalingPoint longer = p;
  longer.axis = "steps";
  longer.steps = longer.value = 6;
  const ScalingRow l = run_scaling_point(longer, s, *lm);
  ASSERT_EQ(l.error, "");
  EXPECT_GE(l.observed_steps_mean, std::min(6.0, r.observed_steps_mean));
}

}  // namespace scaling_test

}  // namespace clips::studies
