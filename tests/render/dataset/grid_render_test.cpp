#include "render/grid_render_test.hpp"

namespace clips::render {
namespace grid_render_test {
// Renders every dataset map at 64 and 16 px per cell, for checks and for eyes.
TEST(GridRender, DatasetMaps) {
  const auto dir = dataset_dir() / "doors-keys-gems" / "problems";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "dataset not found at " << dir;
  int maps = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    GridScene s = parse_ascii_map(read_text(entry.path()));
    ASSERT_GT(s.width, 0);
    s.title = "Problem " + entry.path().stem().string();
    s.caption = "Can you pass me the red key?";
    s.bars = {{"gem1", "red", 0.55}, {"gem2", "yellow", 0.25}, {"gem3", "blue", 0.15}, {"gem4", "green", 0.05}};
    // Show a held key and an open door so every element appears.
    for (auto& o : s.objects)
      if (o.kind == ObjectKind::Key) {
        o.held_by = "robot", o.x = o.y = -1;
        break;
      }
    for (auto& o : s.objects)
      if (o.kind == ObjectKind::Door) {
        o.locked = false;
        break;
      }
    if (const GridObject* h = s.find("human"))
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        if (s.in_grid(h->x + dx, h->y + dy) && !s.wall(h->x + dx, h->y + dy)) {
          s.traces = {{"human", {{h->x + dx, h->y + dy}, {h->x, h->y}}}};
          break;
        }
    for (int cell : {64, 16}) {
      RenderOptions o;
      o.cell_px = cell;
      const auto path = out_dir() / ("dkg-" + entry.path().stem().string() + "-" + std::to_string(cell) + ".png");
      write_png(s, path, o);
      const Image back = read_png(path);
      const GridLayout L = layout(s, o);
      EXPECT_EQ(back.width, L.width);
      EXPECT_EQ(back.height, L.height);
      for (int y = 1; y <= s.height; ++y)
        for (int x = 1; x <= s.width; ++x)
          if (s.wall(x, y)) {
            const Rect r = L.cell_rect(x, y);
            ASSERT_EQ(back.at(r.x + r.w / 2, r.y + r.h / 2), theme::wall) << path << " " << x << "," << y;
          }
    }
    ++maps;
  }
  EXPECT_GE(maps, 10);
}

}  // namespace grid_render_test

}  // namespace clips::render
