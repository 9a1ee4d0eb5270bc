#pragma once
// The includes, helpers and fixtures of the render tests in grid_render_test.cpp, shared by
// the files of that name in tests/render/ and its label folders
// (docs/testing.md, "Labels").
#include <gtest/gtest.h>

#include <cmath>

#include "render/render.hpp"
#include "render/theme.hpp"
#include "support.hpp"

namespace clips::render {
namespace grid_render_test {

using namespace testing;

// A 6x4 room: wall column at x=3 except a locked red door at (3,2).
GridScene small_scene() {
  GridScene s(6, 4);
  for (int y = 1; y <= 4; ++y) s.set_wall(3, y);
  s.set_wall(3, 2, false);
  s.objects = {
      {"key1", ObjectKind::Key, "red", 1, 1},
      {"door1", ObjectKind::Door, "red", 3, 2, "", true},
      {"gem1", ObjectKind::Gem, "blue", 6, 4},
      {"human", ObjectKind::Human, "", 1, 4},
      {"robot", ObjectKind::Robot, "", 5, 1},
  };
  s.active_agent = "human";
  s.caption = "Can you pass me the red key?";
  return s;
}

Rect inner(const Rect& r, int by) { return {r.x + by, r.y + by, r.w - 2 * by, r.h - 2 * by}; }

}  // namespace grid_render_test
using namespace grid_render_test;
}  // namespace clips::render
