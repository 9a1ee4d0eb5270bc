#pragma once
// The includes, helpers and fixtures of the studies tests in scaling_test.cpp, shared by
// the files of that name in tests/studies/ and its label folders
// (docs/testing.md, "Labels").
// `clips bench --scaling` (studies/scaling.hpp): the points of each axis, the
// CSV line round trip, the SVG chart, and one tiny point run end to end.
#include "studies/scaling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "language/listener.hpp"
#include "test_paths.hpp"
#include "util/error.hpp"

namespace clips::studies {
namespace scaling_test {

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

ScalingRow sample_row(const std::string& axis, int value, double ms) {
  ScalingRow r;
  r.point.axis = axis;
  r.point.value = value;
  r.plans = 3;
  r.belief_steps = 40;
  r.decisions = 20;
  r.belief_median_ms = ms;
  r.belief_p95_ms = 4 * ms;
  r.decision_median_ms = ms / 10;
  r.decision_p95_ms = ms / 2;
  r.max_rss_mb = 123.4;
  r.p_true_mean = 0.625;
  return r;
}

}  // namespace scaling_test
using namespace scaling_test;
}  // namespace clips::studies
