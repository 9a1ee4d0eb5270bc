// Grounding and simulation: the bit-matrix walls, turn-taking, existential
// goals, conditional effects, action costs, and malformed plans.
#include <gtest/gtest.h>

#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "test_paths.hpp"

using namespace clips;
using namespace clips::pddl;

namespace {

std::shared_ptr<Domain> dkg_domain() {
  return std::make_shared<Domain>(load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
}

// 4 columns x 3 rows; one wall at row 2, column 3 (set-index walls true 2 3).
const char* kGrid = R"(
(define (problem grid) (:domain doors-keys-gems)
  (:objects door1 - door key1 key2 - key gem1 - gem red blue - color robot - robot human - human)
  (:init (= (walls) (new-bit-matrix false 3 4))
         (= (walls) (set-index walls true 2 3))
         (= (xloc human) 2) (= (yloc human) 2)
         (= (xloc robot) 1) (= (yloc robot) 1)
         (= (xloc key1) 1) (= (yloc key1) 1) (iscolor key1 red)
         (= (xloc key2) 4) (= (yloc key2) 3) (iscolor key2 blue)
         (= (xloc door1) 2) (= (yloc door1) 3) (iscolor door1 red) (locked door1)
         (= (xloc gem1) 4) (= (yloc gem1) 1) (iscolor gem1 red)
         (forbidden robot gem1)
         (active human) (next-turn human robot) (next-turn robot human))
  (:goal (has human gem1)))
)";

struct Grid {
  std::shared_ptr<Domain> d = dkg_domain();
  std::shared_ptr<Problem> p = std::make_shared<Problem>(parse_problem(*d, kGrid, "grid.pddl"));
  Task t{d, p, GroundingOptions{{"frozen"}, {}, false, false}};

  std::vector<std::string> names(const State& s) {
    std::vector<std::string> out;
    for (ActionId a : t.applicable_actions(s)) out.push_back(t.action_name(a));
    return out;
  }
  State run(const std::vector<std::string>& steps) {
    State s = t.initial_state();
    for (auto& step : steps) {
      auto a = t.find_action(step);
      EXPECT_TRUE(a) << step;
      EXPECT_TRUE(t.applicable(*a, s.data())) << step;
      s = t.apply(s, *a);
    }
    return s;
  }
};

}  // namespace

TEST(Grounding, FoldsStaticFactsAndKeepsDynamicOnes) {
  Grid g;
  // Static: walls, colours, next-turn, forbidden, door positions.
  EXPECT_LT(g.t.atom("iscolor", {"key1", "red"}).bit, 0);
  EXPECT_TRUE(g.t.atom("iscolor", {"key1", "red"}).value);
  EXPECT_LT(g.t.fluent("xloc", {"door1"}).slot, 0);
  EXPECT_EQ(g.t.fluent("xloc", {"door1"}).value, 2);
  // The robot may never hold the gem, so that atom is folded to false.
  EXPECT_LT(g.t.atom("has", {"robot", "gem1"}).bit, 0);
  EXPECT_FALSE(g.t.atom("has", {"robot", "gem1"}).value);
  // Dynamic: positions of agents and keys, locks, turns; frozen is kept on request.
  EXPECT_GE(g.t.fluent("xloc", {"key1"}).slot, 0);
  EXPECT_GE(g.t.atom("locked", {"door1"}).bit, 0);
  EXPECT_GE(g.t.atom("frozen", {"robot"}).bit, 0);
  EXPECT_FALSE(g.t.find_action("(pickup robot gem1)"));
  EXPECT_FALSE(g.t.find_action("(unlock human key2 door1)"));  // colours differ
  EXPECT_TRUE(g.t.find_action("(unlock human key1 door1)"));
  EXPECT_LE(g.t.num_words(), 4);  // 25 bits + 8 int16 fluents
}

TEST(BitMatrix, RowIsYColumnIsXOneBased) {
  Grid g;
  // Human at (x=2, y=2): the wall at (x=3, y=2) blocks `right`; the locked
  // door at (x=2, y=3) blocks `down`.
  auto acts = g.names(g.t.initial_state());
  EXPECT_EQ(acts, (std::vector<std::string>{"(up human)", "(left human)", "(wait human)"}));
  auto w = g.t.fluent("walls", {});
  ASSERT_NE(w.matrix, nullptr);
  EXPECT_EQ(w.matrix->rows, 3);
  EXPECT_EQ(w.matrix->cols, 4);
  EXPECT_TRUE(w.matrix->get(1, 2));   // 0-based (row 1, col 2) = 1-based (2, 3)
  EXPECT_FALSE(w.matrix->get(2, 1));
}

TEST(BitMatrix, GridEdgesUseWidthAndHeight) {
  Grid g;
  // Robot at (1,1) after the human waits: it cannot go up or left (edges).
  State s = g.run({"(wait human)"});
  auto acts = g.names(s);
  EXPECT_EQ(acts, (std::vector<std::string>{"(pickup robot key1)", "(down robot)", "(right robot)", "(wait robot)"}));
}

TEST(TurnTaking, AgentsStrictlyAlternate) {
  Grid g;
  State s = g.t.initial_state();
  for (int i = 0; i < 6; ++i) {
    auto acts = g.names(s);
    const std::string who = i % 2 == 0 ? "human" : "robot";
    for (auto& a : acts) EXPECT_NE(a.find(who), std::string::npos) << a;
    s = g.t.apply(s, *g.t.find_action("(wait " + who + ")"));
  }
}

TEST(Simulation, PickupUnlockHandoverAndExistentialGoal) {
  Grid g;
  State s = g.run({"(wait human)", "(pickup robot key1)", "(wait human)", "(right robot)"});
  // Robot at (2,1), human at (2,2): adjacent, so hand-over is possible.
  auto robot_has_red = g.t.compile_text("(exists (?k - key) (and (has robot ?k) (iscolor ?k red)))");
  auto robot_has_blue = g.t.compile_text("(exists (?k - key) (and (has robot ?k) (iscolor ?k blue)))");
  EXPECT_TRUE(robot_has_red.holds(s));
  EXPECT_FALSE(robot_has_blue.holds(s));
  s = g.t.apply(s, *g.t.find_action("(wait human)"));
  s = g.t.apply(s, *g.t.find_action("(handover robot human key1)"));
  EXPECT_TRUE(g.t.compile_text("(and (has human key1) (pickedup-by robot key1))").holds(s));
  EXPECT_FALSE(robot_has_red.holds(s));
  // Human at (2,2) is above the door at (2,3): unlock consumes the key.
  s = g.t.apply(s, *g.t.find_action("(unlock human key1 door1)"));
  EXPECT_TRUE(g.t.compile_text("(and (not (locked door1)) (unlocked-by human door1) (unlocked-with key1 door1))").holds(s));
  EXPECT_FALSE(g.t.compile_text("(has human key1)").holds(s));
  EXPECT_EQ(g.t.value(s, g.t.fluent("xloc", {"key1"})), -1);
}

TEST(Simulation, FrozenAgentCanOnlyWaitOrHandOver) {
  Grid g;
  State s = g.run({"(wait human)", "(pickup robot key1)", "(wait human)", "(right robot)", "(wait human)"});
  g.t.set(s, g.t.atom("frozen", {"robot"}), true);
  EXPECT_EQ(g.names(s), (std::vector<std::string>{"(handover robot human key1)", "(wait robot)"}));
}

TEST(Simulation, StatesHashAndCompareByValue) {
  Grid g;
  State a = g.run({"(up human)", "(wait robot)"});
  State b = g.run({"(up human)", "(wait robot)"});
  State c = g.run({"(left human)", "(wait robot)"});
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  EXPECT_NE(a, c);
}

TEST(Plans, UtteranceIndexIsTheNumberOfActionsBefore) {
  PlanFile pf = parse_plan("(up human)\n\n  (wait robot)  \n; Can you help?\n(left human)\n", "p.pddl");
  ASSERT_EQ(pf.actions.size(), 3u);
  ASSERT_EQ(pf.utterances.size(), 1u);
  EXPECT_EQ(pf.utterances[0].text, "Can you help?");
  EXPECT_EQ(pf.utterances[0].index, 2);
  EXPECT_EQ(pf.actions[2].loc.line, 5);
}

TEST(Plans, BadStepsAreExplained) {
  Grid g;
  auto err = [&](const std::string& text) {
    try {
      simulate(g.t, g.t.initial_state(), parse_plan(text, "plan.pddl"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = err("(up human)\n(pickup robot key9)\n");
  EXPECT_NE(e.find("plan.pddl:2:1"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown object 'key9'"), std::string::npos) << e;
  e = err("(jump human)\n");
  EXPECT_NE(e.find("unknown action 'jump'"), std::string::npos) << e;
  e = err("(up human robot)\n");
  EXPECT_NE(e.find("arity mismatch"), std::string::npos) << e;
  e = err("(right human)\n");
  EXPECT_NE(e.find("plan.pddl:1:1"), std::string::npos) << e;
  EXPECT_NE(e.find("(= (get-index walls (yloc human) (+ (xloc human) 1)) false) is false"), std::string::npos) << e;
  e = err("(wait human)\n(pickup robot gem1)\n");
  EXPECT_NE(e.find("(not (forbidden robot gem1)) is false"), std::string::npos) << e;
  e = err("(wait robot)\n");
  EXPECT_NE(e.find("(active robot) is false"), std::string::npos) << e;
  e = err("(pickup human key1\n");
  EXPECT_NE(e.find("malformed action"), std::string::npos) << e;
}

TEST(OtherDomain, TypedBlocksWorldGroundsAndSimulates) {
  auto d = std::make_shared<Domain>(load_domain(paths::examples_dir() + "/blocks/domain.pddl"));
  auto p = std::make_shared<Problem>(load_problem(*d, paths::examples_dir() + "/blocks/p1.pddl"));
  Task t(d, p);
  PlanFile plan = parse_plan(
      "(pick b a)\n(place b table)\n(pick a table)\n(place a b)\n", "blocks-plan");
  // a on b is wanted but b must end on c: (place a b) first, then b cannot move.
  Simulation sim = simulate(t, t.initial_state(), plan);
  EXPECT_DOUBLE_EQ(sim.cost, 6.0);  // two picks at 2, two places at 1
  EXPECT_TRUE(t.compile_text("(on a b)").holds(sim.states.back()));
  EXPECT_EQ(t.value(sim.states.back(), t.fluent("moves", {})), 2);
  // Conditional effect: picking b from a cleared a; picking from the table did not clear it twice.
  EXPECT_TRUE(t.compile_text("(clear a)").holds(sim.states[1]));
  // imply: heavy c may only go on the table.
  State s = sim.states[0];
  s = t.apply(s, *t.find_action("(pick c table)"));
  EXPECT_FALSE(t.find_action("(place c b)"));  // statically impossible, so never grounded
  std::string why = t.explain_inapplicable(d->find_action("place"), {*t.find_object("c"), *t.find_object("b")}, s);
  EXPECT_EQ(why, "precondition (imply (heavy c) (= b table)) is false");
  EXPECT_TRUE(t.applicable(*t.find_action("(place c table)"), s.data()));
  // The problem goal compiles and is not yet reached.
  int nv = 0;
  auto goal = t.compile(*p->goal, std::vector<ObjectId>(p->goal_num_vars + nv, -1));
  EXPECT_FALSE(goal.holds(sim.states.back()));
}
