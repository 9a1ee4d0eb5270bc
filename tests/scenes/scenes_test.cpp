#include "scenes/scenes_test.hpp"

namespace clips::scenes {
namespace scenes_test {
TEST(Scenes, DkgInitialState) {
  auto ds = data::Dataset::load(examples_dkg());
  auto task = ds.task("e1");
  domains::dkg::DkgWorld w(*task);
  auto scene = dkg_scene(w, task->initial_state(), {"hello", "title", {}, {}});
  EXPECT_EQ(scene.width, 9);
  EXPECT_EQ(scene.height, 5);
  EXPECT_TRUE(scene.wall(1, 2));   // walls row 2, columns 1..3
  EXPECT_TRUE(scene.wall(9, 4));
  EXPECT_FALSE(scene.wall(5, 2));
  EXPECT_FALSE(scene.wall(1, 1));
  EXPECT_EQ(object(scene, "human").x, 5);
  EXPECT_EQ(object(scene, "human").y, 3);
  EXPECT_EQ(object(scene, "human").kind, render::ObjectKind::Human);
  EXPECT_EQ(object(scene, "robot").x, 5);
  EXPECT_EQ(object(scene, "robot").y, 4);
  EXPECT_EQ(object(scene, "robot").kind, render::ObjectKind::Robot);
  EXPECT_EQ(object(scene, "key3").colour, "yellow");
  EXPECT_EQ(object(scene, "key3").x, 5);
  EXPECT_EQ(object(scene, "key3").y, 5);
  EXPECT_TRUE(object(scene, "key3").held_by.empty());
  EXPECT_TRUE(object(scene, "door1").locked);
  EXPECT_EQ(object(scene, "door1").colour, "red");
  EXPECT_EQ(object(scene, "gem4").colour, "green");
  EXPECT_EQ(object(scene, "gem4").kind, render::ObjectKind::Gem);
  EXPECT_EQ(scene.active_agent, "human");
  EXPECT_EQ(scene.caption, "hello");
  EXPECT_EQ(scene.title, "title");
}

TEST(Scenes, HeldItemsAndUnlockedDoorsAlongAPlan) {
  auto ds = data::Dataset::load(examples_dkg());
  const auto& p = ds.plan("e1.1.keys");
  auto task = ds.task(p.problem_id);
  domains::dkg::DkgWorld w(*task);
  auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
  auto done = pddl::simulate(*task, obs.states.back(), p.completed);
  // Find the states right after the robot picks key3 up and after the unlock.
  int pick = -1, unlock = -1;
  for (size_t i = 0; i < done.actions.size(); ++i) {
    auto name = task->action_name(done.actions[i]);
    if (name == "(pickup robot key3)") pick = static_cast<int>(i) + 1;
    if (name.rfind("(unlock human key3", 0) == 0) unlock = static_cast<int>(i) + 1;
  }
  ASSERT_GT(pick, 0);
  ASSERT_GT(unlock, pick);
  auto held = dkg_scene(w, done.states[pick]);
  EXPECT_EQ(object(held, "key3").held_by, "robot");
  EXPECT_FALSE(held.in_grid(object(held, "key3").x, object(held, "key3").y));
  EXPECT_TRUE(object(held, "door3").locked);
  auto opened = dkg_scene(w, done.states[unlock]);
  EXPECT_FALSE(object(opened, "door3").locked);
  EXPECT_TRUE(object(opened, "door4").locked);
}

TEST(Scenes, PosteriorBarsUseGemColours) {
  auto ds = data::Dataset::load(examples_dkg());
  auto task = ds.task("e1");
  auto bars = posterior_bars(*task, ds.pack(), {"gem1", "gem2", "gem3", "gem4"}, {0.1, 0.2, 0.3, 0.4});
  ASSERT_EQ(bars.size(), 4u);
  EXPECT_EQ(bars[0].colour, "red");
  EXPECT_EQ(bars[1].colour, "yellow");
  EXPECT_EQ(bars[2].colour, "blue");
  EXPECT_EQ(bars[3].colour, "green");
  EXPECT_DOUBLE_EQ(bars[3].probability, 0.4);
}

TEST(Scenes, PlanFramesObservedThenAssisted) {
  auto ds = data::Dataset::load(examples_dkg());
  const auto& p = ds.plan("e1.1.keys");
  PlanRun run;
  run.goals = {"gem1", "gem2", "gem3", "gem4"};
  for (int t = 0; t <= 4; ++t) run.observed_posterior.push_back({0.25, 0.25, 0.25 + 0.1 * t, 0.25});
  run.final_posterior = {0, 0, 1, 0};
  run.assisted = {"(right human)", "(down robot)"};
  auto f = plan_frames(ds, p, run);
  ASSERT_EQ(f.size(), 4u + 1 + 2);
  EXPECT_EQ(f.observed_steps, 4);
  EXPECT_EQ(f.assisted_steps, 2);
  EXPECT_TRUE(f.grid[0].caption.empty());            // utterance comes after 4 actions
  EXPECT_NE(f.grid[4].caption.find("yellow key"), std::string::npos);
  EXPECT_NE(f.grid[6].caption.find("yellow key"), std::string::npos);
  EXPECT_DOUBLE_EQ(f.grid[2].bars[2].probability, 0.45);
  EXPECT_DOUBLE_EQ(f.grid[6].bars[2].probability, 1.0);
  EXPECT_EQ(object(f.grid[6], "robot").y, 5);
  run.assisted = {"(fly robot)"};
  EXPECT_THROW(plan_frames(ds, p, run), InputError);
}

}  // namespace scenes_test

}  // namespace clips::scenes
