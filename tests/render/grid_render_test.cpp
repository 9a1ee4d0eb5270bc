#include "render/grid_render_test.hpp"

namespace clips::render {
namespace grid_render_test {
TEST(GridRender, ImageSizeFollowsLayout) {
  for (int cell : {16, 32, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const GridScene s = small_scene();
    const GridLayout L = layout(s, o);
    const Image img = render_png(s, o);
    EXPECT_EQ(img.width, L.width);
    EXPECT_EQ(img.height, L.height);
    EXPECT_EQ(L.grid.w, 6 * cell);
    EXPECT_EQ(L.grid.h, 4 * cell);
    EXPECT_EQ(L.show_labels, cell >= 28);
  }
}

TEST(GridRender, WallCellHasWallColour) {
  for (int cell : {16, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const GridScene s = small_scene();
    const GridLayout L = layout(s, o);
    const Image img = render_png(s, o);
    const Rect w = L.cell_rect(3, 3);
    EXPECT_EQ(count_colour(img, w, theme::wall), w.w * w.h) << "cell " << cell;
    const Rect f = L.cell_rect(2, 3);  // empty floor
    EXPECT_EQ(img.at(f.x + f.w / 2, f.y + f.h / 2), theme::floor);
  }
}

TEST(GridRender, RedKeyCellContainsRed) {
  for (int cell : {16, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const GridScene s = small_scene();
    const GridLayout L = layout(s, o);
    const Image img = render_png(s, o);
    const Rect k = L.cell_rect(1, 1);
    const Rgb r = named_colour("red");
    const int red = count_pixels(img, k, [r](Rgb c) { return near(c, r, 24); });
    EXPECT_GT(red, k.w * k.h / 12) << "cell " << cell;
    EXPECT_EQ(count_colour(img, L.cell_rect(6, 4), named_colour("red")), 0);
    EXPECT_GT(count_colour(img, L.cell_rect(6, 4), named_colour("blue")), 0);
  }
}

TEST(GridRender, LockedAndOpenDoorsDiffer) {
  GridScene s = small_scene();
  RenderOptions o;
  o.cell_px = 48;
  const GridLayout L = layout(s, o);
  const Rect d = inner(L.cell_rect(3, 2), 2);
  const Rgb red = named_colour("red");
  const int locked_red = count_colour(render_png(s, o), d, red);
  s.objects[1].locked = false;
  const Image open = render_png(s, o);
  const int open_red = count_colour(open, d, red);
  EXPECT_GT(locked_red, d.w * d.h / 2);  // a solid coloured block
  EXPECT_GT(open_red, 0);                // the outline
  EXPECT_LT(open_red, locked_red / 2);
  EXPECT_GT(count_colour(open, d, tint(red, 0.78)), d.w * d.h / 3);  // see-through floor
}

TEST(GridRender, ActiveAgentHasMarker) {
  GridScene s = small_scene();
  for (int cell : {16, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const GridLayout L = layout(s, o);
    s.active_agent = "human";
    Image img = render_png(s, o);
    EXPECT_GT(count_colour(img, L.cell_rect(1, 4), theme::marker), cell) << cell;
    EXPECT_EQ(count_colour(img, L.cell_rect(5, 1), theme::marker), 0);
    EXPECT_GT(count_colour(img, L.cell_rect(1, 4), theme::human), cell);
    s.active_agent = "robot";
    img = render_png(s, o);
    EXPECT_EQ(count_colour(img, L.cell_rect(1, 4), theme::marker), 0);
    EXPECT_GT(count_colour(img, L.cell_rect(5, 1), theme::marker), cell);
    EXPECT_GT(count_colour(img, L.cell_rect(5, 1), theme::robot), cell);
  }
}

TEST(GridRender, CaptionAreaHasText) {
  GridScene s = small_scene();
  const GridLayout L = layout(s);
  ASSERT_GT(L.caption.h, 0);
  auto dark = [](Rgb c) { return c.r < 100 && c.g < 100 && c.b < 100; };
  EXPECT_GT(count_pixels(render_png(s), L.caption, dark), 50);
  s.caption.clear();
  EXPECT_EQ(count_pixels(render_png(s), layout(s).caption, dark), 0);
}

TEST(GridRender, LongCaptionWrapsInsideWidth) {
  GridScene s = small_scene();
  s.caption = std::string(40, 'x') + " " + "I'll get the blue key. Can you pick up a red key and "
              "bring it to me, and then maybe also open the yellow door on the left?";
  RenderOptions o;
  o.cell_px = 16;
  const GridLayout L = layout(s, o);
  EXPECT_GE(L.caption_lines, 3);
  const Image img = render_png(s, o);
  EXPECT_EQ(img.width, L.width);
  // Nothing is drawn in the right margin.
  const Rect margin{L.caption.x + L.caption.w + 1, L.caption.y, img.width - L.caption.x - L.caption.w - 1, L.caption.h};
  EXPECT_EQ(count_colour(img, margin, theme::background), margin.w * margin.h);
}

TEST(GridRender, BarsAreProportional) {
  GridScene s = small_scene();
  s.bars = {{"gem1", "red", 0.6}, {"gem2", "yellow", 0.3}, {"gem3", "blue", 0.1}, {"gem4", "green", 0.0}};
  for (int cell : {16, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const GridLayout L = layout(s, o);
    const Image img = render_png(s, o);
    ASSERT_EQ(L.bars.size(), 4u);
    EXPECT_GT(L.chart.x, L.grid.x + L.grid.w);  // beside the grid
    for (std::size_t i = 0; i < 4; ++i) {
      const Rect& b = L.bars[i];
      const Rgb c = named_colour(s.bars[i].colour);
      const int y = b.y + b.h / 2;
      int run = 0;
      while (img.at(b.x + run, y) == c) ++run;
      EXPECT_NEAR(run, s.bars[i].probability * L.bar_max, 1.0) << i;
    }
    // Measured lengths keep the ratio of the probabilities.
    EXPECT_NEAR(static_cast<double>(L.bars[0].w) / L.bars[1].w, 2.0, 0.05);
  }
}

TEST(GridRender, HeldItemsAppearInInventory) {
  GridScene s = small_scene();
  s.objects[0].x = s.objects[0].y = -1;
  s.objects[0].held_by = "robot";
  const GridLayout L = layout(s);
  const Image img = render_png(s);
  EXPECT_EQ(count_colour(img, L.cell_rect(1, 1), named_colour("red")), 0);
  EXPECT_GT(count_colour(img, L.inventory, named_colour("red")), 20);
}

TEST(GridRender, SharedCellShowsBothAgentsAndTheItem) {
  GridScene s = small_scene();
  s.objects[3].x = 1, s.objects[3].y = 1;  // human onto the key
  s.objects[4].x = 1, s.objects[4].y = 1;  // robot too
  RenderOptions o;
  o.cell_px = 64;
  const GridLayout L = layout(s, o);
  const Image img = render_png(s, o);
  const Rect c = L.cell_rect(1, 1);
  EXPECT_GT(count_colour(img, c, theme::human), 100);
  EXPECT_GT(count_colour(img, c, theme::robot), 100);
  EXPECT_GT(count_colour(img, c, named_colour("red")), 30);
}

TEST(GridRender, FramesShareOneSize) {
  GridScene a = small_scene(), b = small_scene();
  a.caption.clear();
  b.caption = "A much longer caption that needs more than one line when the cells are only sixteen pixels";
  b.bars = {{"gem1", "red", 1.0}};
  b.title = "step 2";
  RenderOptions o;
  o.cell_px = 16;
  const auto frames = render_frames({a, b}, o);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].width, frames[1].width);
  EXPECT_EQ(frames[0].height, frames[1].height);
}

TEST(GridRender, RejectsBadScene) {
  GridScene s(3, 3);
  s.walls.pop_back();
  EXPECT_THROW(render_png(s), std::invalid_argument);
  EXPECT_THROW(render_png(GridScene{}), std::invalid_argument);
}

TEST(GridRender, TracesAreDrawn) {
  GridScene s = small_scene();
  s.caption.clear();
  s.traces = {{"human", {{1, 4}, {2, 4}, {2, 3}, {2, 2}, {2, 1}}}};
  RenderOptions o;
  o.cell_px = 32;
  const GridLayout L = layout(s, o);
  const Image with = render_png(s, o);
  EXPECT_LT(count_colour(with, L.cell_rect(2, 3), theme::floor),
            count_colour(render_png(small_scene(), o), L.cell_rect(2, 3), theme::floor));
}

}  // namespace grid_render_test

}  // namespace clips::render
