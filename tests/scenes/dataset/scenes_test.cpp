#include "scenes/scenes_test.hpp"

namespace clips::scenes {
namespace scenes_test {
TEST(Scenes, VirtualHomeSceneIfDatasetPresent) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset";
  auto ds = data::Dataset::load(clips::paths::vh_dataset());
  const auto& p = ds.plans().front();
  auto task = ds.task(p.problem_id);
  domains::vh::VhWorld w(*task);
  auto s = task->initial_state();
  auto scene = vh_scene(ds.pack(), w, s);
  EXPECT_EQ(scene.fixtures.size(), w.fixtures().size());
  // The pack's colours, read from its "#rrggbb" strings.
  ASSERT_TRUE(scene.type_colours.count("plate"));
  EXPECT_EQ(scene.type_colours.at("plate"), (render::Rgb{168, 200, 245}));
  EXPECT_EQ(scene.type_colours.size(), ds.pack().spec().scene_colours.size());
  size_t items = 0;
  for (auto& f : scene.fixtures)
    for (auto& pile : f.piles) items += pile.size();
  size_t held = 0;
  for (auto& a : scene.agents) held += a.held.size();
  EXPECT_EQ(items + held, w.items().size());
  ASSERT_EQ(scene.agents.size(), 2u);
  EXPECT_FALSE(scene.active_agent.empty());
}

}  // namespace scenes_test

}  // namespace clips::scenes
