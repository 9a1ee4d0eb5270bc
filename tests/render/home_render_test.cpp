#include <gtest/gtest.h>

#include "render/render.hpp"
#include "render/theme.hpp"
#include "support.hpp"

namespace clips::render {
namespace {

using namespace testing;

// Problem 2 of VirtualHome (table setting), a few steps in.
HomeScene table_setting() {
  HomeScene s;
  s.fixtures = {{"table1", {{"plate1"}, {"cutleryfork1"}}},
                {"cabinet1", {{"bowl1", "bowl2", "bowl3", "bowl4"}}},
                {"cabinet2", {{"plate2", "plate3", "plate4"}}},
                {"cabinet3", {}},
                {"cabinet4", {{"cutleryfork2", "cutleryfork3", "cutleryfork4"},
                              {"cutleryknife1", "cutleryknife2", "cutleryknife3", "cutleryknife4"}}},
                {"cabinet5", {}}};
  s.agents = {{"actor", ObjectKind::Human, "cabinet2", {"plate2"}},
              {"helper", ObjectKind::Robot, "cabinet4", {}}};
  s.active_agent = "helper";
  // Tables and plates have colours of their own; cabinets, bowls, forks and
  // knives do not.
  s.type_colours = {{"table", card_header_colours()[0]}, {"plate", pastel_colours()[4]}};
  s.caption = "Could you get the forks and knives?";
  s.title = "VirtualHome 2.1";
  const char* labels[] = {"set_table1", "set_table2", "set_table3", "set_table4",
                          "set_table1b", "set_table2b", "set_table3b", "set_table4b",
                          "plate1", "plate2", "plate3", "plate4"};
  const double p[] = {0.02, 0.40, 0.10, 0.03, 0.05, 0.25, 0.05, 0.02, 0.02, 0.03, 0.02, 0.01};
  for (int i = 0; i < 12; ++i) s.bars.push_back({labels[i], "blue", p[i]});
  return s;
}

TEST(HomeRender, LayoutAndPixels) {
  const HomeScene s = table_setting();
  for (int cell : {16, 32, 64}) {
    RenderOptions o;
    o.cell_px = cell;
    const HomeLayout L = layout(s, o);
    const Image img = render_png(s, o);
    EXPECT_EQ(img.width, L.width);
    EXPECT_EQ(img.height, L.height);
    ASSERT_EQ(L.fixture_boxes.size(), 6u);
    // The table card has its own header colour and the plate's; a cabinet's
    // header is grey, and bowls get their hashed pastel.
    EXPECT_GT(count_colour(img, L.fixture_boxes[0], card_header_colours()[0]), 100);
    EXPECT_GT(count_colour(img, L.fixture_boxes[0], pastel_colours()[4]), 100);
    EXPECT_EQ(count_colour(img, L.fixture_boxes[3], card_header_colours()[0]), 0);
    EXPECT_GT(count_colour(img, L.fixture_boxes[3], theme::neutral), 100);
    EXPECT_GT(count_colour(img, L.fixture_boxes[1], hashed_pastel("bowl")), 100);
    // The helper (active) stands at cabinet4 with the marker; the actor does not have one.
    EXPECT_GT(count_colour(img, L.fixture_boxes[4], theme::robot), 20);
    EXPECT_GT(count_colour(img, L.fixture_boxes[4], theme::marker), 10);
    EXPECT_EQ(count_colour(img, L.fixture_boxes[2], theme::marker), 0);
    EXPECT_GT(count_colour(img, L.fixture_boxes[2], theme::human), 20);
    auto dark = [](Rgb c) { return c.r < 100 && c.g < 100 && c.b < 100; };
    EXPECT_GT(count_pixels(img, L.caption, dark), 50);
    ASSERT_EQ(L.bars.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
      const Rect& b = L.bars[i];
      int run = 0;
      while (img.at(b.x + run, b.y + b.h / 2) == named_colour("blue")) ++run;
      EXPECT_NEAR(run, s.bars[i].probability * L.bar_max, 1.0) << i;
    }
    write_png(img, out_dir() / ("vh-2-" + std::to_string(cell) + ".png"));
  }
}

TEST(HomeRender, FramesShareOneSize) {
  HomeScene a = table_setting(), b = table_setting();
  a.caption.clear();
  a.bars.clear();
  // Everything ends up on the table: a taller card.
  for (auto& f : b.fixtures)
    if (f.name != "table1")
      for (auto& pile : f.piles) b.fixtures[0].piles.push_back(pile), pile.clear();
  const auto frames = render_frames({a, b});
  EXPECT_EQ(frames[0].width, frames[1].width);
  EXPECT_EQ(frames[0].height, frames[1].height);
  write_png(frames[1], out_dir() / "vh-2-all-on-table.png");
}

}  // namespace
}  // namespace clips::render
