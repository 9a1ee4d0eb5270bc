// Literal-listener assistance (two-phase planning, naive groundings) on a
// hand-made map:
//
//   x: 1 2 3 4 5 6 7 8 9
//   y1 . . . . . . . . .
//   y2 . . . h . g . . .     human (4,2), gem1 at (6,2): the true goal
//   y3 . . . . . . . . .
//   y4 W W W W W W W W W
//   y5 m b . . . . . r R     robot (1,5), key2 blue (2,5), key1 red (8,5), door1 red (9,5)
//
// The robot's corridor and the human's room do not meet, so whatever the
// robot is asked, the human then fetches the gem alone.
#include <gtest/gtest.h>

#include <algorithm>

#include "assist/literal.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "commands/grounding.hpp"
#include "dkg_profiles.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

const char* kMap = R"(
(define (problem corridor) (:domain doors-keys-gems)
  (:objects door1 - door key1 key2 - key gem1 - gem red yellow blue green - color robot - robot human - human)
  (:init (= (walls) (new-bit-matrix false 5 9))
    (= (walls) (set-index walls true 4 1)) (= (walls) (set-index walls true 4 2))
    (= (walls) (set-index walls true 4 3)) (= (walls) (set-index walls true 4 4))
    (= (walls) (set-index walls true 4 5)) (= (walls) (set-index walls true 4 6))
    (= (walls) (set-index walls true 4 7)) (= (walls) (set-index walls true 4 8))
    (= (walls) (set-index walls true 4 9))
    (= (xloc door1) 9) (= (yloc door1) 5) (iscolor door1 red) (locked door1)
    (= (xloc key1) 8) (= (yloc key1) 5) (iscolor key1 red)
    (= (xloc key2) 2) (= (yloc key2) 5) (iscolor key2 blue)
    (= (xloc gem1) 6) (= (yloc gem1) 2) (iscolor gem1 green) (forbidden robot gem1)
    (= (xloc human) 4) (= (yloc human) 2) (= (xloc robot) 1) (= (yloc robot) 5)
    (active human) (next-turn human robot) (next-turn robot human))
  (:goal (has human gem1))))";

// Small enough that the joint search for the robot's pick-up (the human may
// wander the room meanwhile) runs out, large enough for the same search with
// the human frozen and for the human's walk to the gem.
constexpr size_t kNodes = 100;

struct World {
  domains::PackPtr pack = domains::builtin_pack("doors-keys-gems");
  std::shared_ptr<pddl::Domain> d = std::make_shared<pddl::Domain>(
      pddl::load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
  std::shared_ptr<pddl::Problem> p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, kMap, "corridor"));
  std::shared_ptr<pddl::Task> task =
      std::make_shared<pddl::Task>(d, p, pddl::GroundingOptions{{"frozen"}, {}, false, false});
  language::LiteralListenerSetup listener = language::literal_listener_setup(pack);

  std::shared_ptr<heuristics::Heuristic> blind() const { return pack->make_heuristic("blind", *task); }

  assist::LiteralSetup setup() const {
    assist::LiteralSetup ls;
    ls.world.task = task;
    ls.world.start = task->initial_state();
    ls.world.horizon = 60;
    ls.truth = std::make_shared<model::Specification>(task, "(has human gem1)", fixtures::dkg_profile(1));
    ls.config = listener.config;
    ls.make_heuristic = [this] { return blind(); };
    ls.is_option = [](const std::string& o) { return o.rfind("door", 0) == 0; };
    ls.max_nodes = kNodes;
    ls.objects_by_type = {{"key", {"key1", "key2"}}, {"door", {"door1"}}};
    ls.facts = commands::parse_terms("(iscolor key1 red) (iscolor key2 blue) (iscolor door1 red)");
    return ls;
  }

  // The listener's reading: this one command, with certainty.
  language::ListenerResult reading(const std::string& display_form) const {
    const auto all = language::literal_commands(*task, task->initial_state(), listener);
    auto it = std::find_if(all.begin(), all.end(),
                           [&](const commands::Command& c) { return c.display_form() == display_form; });
    EXPECT_NE(it, all.end()) << display_form;
    language::ListenerResult r;
    r.utterance = "test";
    if (it != all.end()) r.commands.push_back({*it, 0.0, 1.0});
    return r;
  }

  bool contains(const std::vector<pddl::ActionId>& plan, const std::string& action) const {
    return std::any_of(plan.begin(), plan.end(), [&](pddl::ActionId a) { return task->action_name(a) == action; });
  }
};

}  // namespace

// Phase 1 plans with the human frozen when the joint search fails; phase 2
// then starts from that plan carried out in s_T, where the human is free.
// (It used to start from the frozen state, so the human could never finish.)
TEST(LiteralTwoPhase, TheHumanFrozenForPhaseOneIsFreeInPhaseTwo) {
  World w;
  const auto ls = w.setup();
  const std::string pick = "(pickup you ?key1) where (iscolor ?key1 red)";
  const auto ranked = w.reading(pick);
  ASSERT_EQ(ranked.commands.size(), 1u);

  // The situation this test needs: only the frozen search finds the command's plan.
  const model::Specification cmd(w.task, ranked.commands[0].command.to_goal_formula(ls.config), fixtures::dkg_profile(1));
  search::SearchOptions so;
  so.max_nodes = kNodes;
  EXPECT_EQ(search::plan(cmd, *w.blind(), ls.world.start, so).status, search::SearchStatus::MaxNodes);
  EXPECT_EQ(search::plan(cmd, *w.blind(), model::freeze(*w.task, ls.world.start, "human"), so).status,
            search::SearchStatus::Success);

  for (bool naive : {false, true}) {
    const auto run = assist::literal_assist(ls, ranked, naive, 1);
    EXPECT_DOUBLE_EQ(run.command_success, 1.0) << "naive " << naive;
    EXPECT_DOUBLE_EQ(run.result.success, 1.0) << "naive " << naive;
    EXPECT_TRUE(w.contains(run.result.plan, "(pickup robot key1)")) << "naive " << naive;
    EXPECT_TRUE(w.contains(run.result.plan, "(pickup human gem1)")) << "naive " << naive;
    EXPECT_EQ(run.result.noops, 0);
  }
}

// The naive listener counts options over every grounding, then, as the
// reference does, plans only for those whose last action is not statically
// impossible: "unlock the red door" grounds with the blue key too, which can
// never open it.
TEST(LiteralNaive, StaticallyImpossibleGroundingsAreNotPlannedFor) {
  World w;
  auto ls = w.setup();
  ls.max_nodes = 1u << 16;
  const auto ranked = w.reading("(unlock you ?key1 ?door1) where (iscolor ?door1 red)");
  ASSERT_EQ(ranked.commands.size(), 1u);
  EXPECT_EQ(commands::naive_groundings(ranked.commands[0].command, ls.objects_by_type, ls.facts).size(), 2u);

  const auto run = assist::literal_assist(ls, ranked, /*naive=*/true, 1);
  EXPECT_DOUBLE_EQ(run.result.options.at("door1"), 1.0);
  // Only (unlock robot key1 door1) is planned for, and it succeeds.
  EXPECT_DOUBLE_EQ(run.command_success, 1.0);
  EXPECT_DOUBLE_EQ(run.result.success, 1.0);
  EXPECT_TRUE(w.contains(run.result.plan, "(unlock robot key1 door1)"));
}
