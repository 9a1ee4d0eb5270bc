// The PDDL a user brings from the planning competitions (issue 64): the
// tokenizer's variables, union types, derived predicates, metrics, numbers
// that are not integers, type declarations, and grounding by reachability.
#include <gtest/gtest.h>

#include <chrono>

#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "pddl/support.hpp"
#include "pddl/task.hpp"

using namespace clips;
using namespace clips::pddl;

namespace {

using clips::pddl::testing::error_of;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Parsed {
  std::shared_ptr<Domain> d;
  std::shared_ptr<Problem> p;
};
Parsed parse(const std::string& dom, const std::string& prob) {
  Parsed x;
  x.d = std::make_shared<Domain>(parse_domain(dom, "d.pddl"));
  x.p = std::make_shared<Problem>(parse_problem(*x.d, prob, "p.pddl"));
  return x;
}
std::shared_ptr<const Task> ground(const std::string& dom, const std::string& prob, GroundingOptions o = {}) {
  Parsed x = parse(dom, prob);
  return std::make_shared<Task>(x.d, x.p, o);
}

TEST(Tokenizer, AQuestionMarkStartsAVariableEvenRightAfterAName) {
  const auto e = read_one_sexpr("(aircraft?a ?b?c)", "<t>");
  ASSERT_EQ(e.items.size(), 4u);
  EXPECT_EQ(e.items[0].atom, "aircraft");
  EXPECT_EQ(e.items[1].atom, "?a");
  EXPECT_EQ(e.items[2].atom, "?b");
  EXPECT_EQ(e.items[3].atom, "?c");
}

const char* kStorage = R"((define (domain store)
  (:requirements :typing)
  (:types crate area - object depot - area)
  (:predicates (in ?x - (either area crate) ?p - depot) (seen ?x - (either area crate)))
  (:action look :parameters (?x - (either crate area) ?p - depot)
    :precondition (in ?x ?p) :effect (seen ?x)))
)";

TEST(UnionTypes, EitherParametersTakeObjectsOfEachMemberType) {
  auto t = ground(kStorage, R"((define (problem s) (:domain store)
    (:objects c1 c2 - crate a1 - area d1 - depot)
    (:init (in c1 d1) (in a1 d1) (in d1 d1)) (:goal (and (seen c1) (seen a1)))))");
  // (look c1 d1), (look a1 d1), and d1 is an area too; c2 is in no depot.
  EXPECT_EQ(t->num_actions(), 3);
  EXPECT_TRUE(t->find_action("(look c1 d1)"));
  EXPECT_TRUE(t->find_action("(look d1 d1)"));
  EXPECT_FALSE(t->find_action("(look c2 d1)"));
  // An object may not be given a union type.
  const std::string e = error_of([&] {
    parse(kStorage, "(define (problem s) (:domain store) (:objects x - (either crate area)) (:init) (:goal (and)))");
  });
  EXPECT_TRUE(has(e, "p.pddl:1:")) << e;
  EXPECT_TRUE(has(e, "union type")) << e;
}

TEST(Types, AnUndeclaredParentIsATypeAndTwoParentsAreALocatedError) {
  const std::string dom = R"((define (domain ty) (:requirements :typing)
  (:types car - vehicle)
  (:predicates (at ?c - car)))
)";
  // "vehicle" is never declared itself: a type under object, as other
  // planners read it.
  EXPECT_EQ(error_of([&] { parse_domain(dom, "ty.pddl"); }), "");
  const auto d = parse_domain(dom, "ty.pddl");
  const auto car = d.find_type("car"), vehicle = d.find_type("vehicle");
  ASSERT_TRUE(car && vehicle);
  EXPECT_TRUE(d.is_subtype(*car, *vehicle));
  std::string twice = dom;
  twice.replace(twice.find("car - vehicle"), 13, "car - vehicle\n car - toy vehicle toy");
  const std::string e = error_of([&] { parse_domain(twice, "ty.pddl"); });
  EXPECT_TRUE(has(e, "ty.pddl:3:")) << e;
  EXPECT_TRUE(has(e, "declared twice with two parents")) << e;
}

const char* kCounter = R"((define (domain counter)
  (:requirements :strips :numeric-fluents :action-costs)
  (:predicates (done))
  (:functions (total-cost) (moves) (fuel))
  (:action step :parameters () :precondition (not (done))
    :effect (and (done) (increase (moves) 2) (decrease (fuel) 1) (increase (total-cost) 5))))
)";

std::string counter_problem(const std::string& metric) {
  return "(define (problem c) (:domain counter) (:init (= (moves) 0) (= (fuel) 9) (= (total-cost) 0))"
         " (:goal (done)) " + metric + ")";
}

TEST(Metric, MinimizeALinearExpressionOfFluentsGivesEachActionItsCost) {
  EXPECT_EQ(ground(kCounter, counter_problem(""))->action(0).cost, 5);
  EXPECT_EQ(ground(kCounter, counter_problem("(:metric minimize (total-cost))"))->action(0).cost, 5);
  EXPECT_EQ(ground(kCounter, counter_problem("(:metric minimize (moves))"))->action(0).cost, 2);
  EXPECT_EQ(ground(kCounter, counter_problem("(:metric minimize (+ (* 3 (moves)) (- (total-cost) (fuel))))"))
                ->action(0).cost,
            3 * 2 + 5 + 1);
}

TEST(Metric, AnythingElseIsRefusedWithAClearMessage) {
  auto refused = [&](const std::string& metric) {
    return error_of([&] { ground(kCounter, counter_problem(metric)); });
  };
  std::string e = refused("(:metric maximize (moves))");
  EXPECT_TRUE(has(e, "p.pddl:1:")) << e;
  EXPECT_TRUE(has(e, "maximize")) << e;
  EXPECT_TRUE(has(refused("(:metric minimize (total-time))"), "total-time"));
  EXPECT_TRUE(has(refused("(:metric minimize (* (moves) (fuel)))"), "linear"));
  // Negative: the action would pay -1 for using fuel.
  e = refused("(:metric minimize (fuel))");
  EXPECT_TRUE(has(e, "(step) costs -1")) << e;
  // A fluent the metric reads must change by constants.
  const std::string assigning = std::string(kCounter).replace(std::string(kCounter).find("(increase (moves) 2)"), 20,
                                                              "(assign (moves) 2)");
  e = error_of([&] { ground(assigning, counter_problem("(:metric minimize (moves))")); });
  EXPECT_TRUE(has(e, "(moves)")) << e;
  EXPECT_TRUE(has(e, "(step)")) << e;
}

TEST(Numbers, NonIntegerSpellingsNameWhatIsWrong) {
  for (const std::string v : {"1e6", "inf", "0x10", "1.5"}) {
    const std::string e = error_of([&] { ground(kCounter, counter_problem("").replace(counter_problem("").find("(= (fuel) 9)"), 12, "(= (fuel) " + v + ")")); });
    EXPECT_TRUE(has(e, "p.pddl:1:")) << v << ": " << e;
    EXPECT_TRUE(has(e, "'" + v + "'")) << e;
    EXPECT_FALSE(has(e, "unknown object")) << e;
  }
  EXPECT_TRUE(has(error_of([&] { ground(kCounter, counter_problem("").replace(counter_problem("").find("(= (fuel) 9)"), 12, "(= (fuel) 1e6)")); }),
                  "exponent"));
  EXPECT_TRUE(has(error_of([&] { ground(kCounter, counter_problem("").replace(counter_problem("").find("(= (fuel) 9)"), 12, "(= (fuel) 0x10)")); }),
                  "hexadecimal"));
}

// Fluents: 16-bit in states, so values beyond that are input errors naming the fluent.
TEST(Fluents, ValuesBeyondWhatStatesHoldAreInputErrors) {
  const char* dom = R"((define (domain grow) (:requirements :numeric-fluents)
  (:functions (n))
  (:action double :parameters () :precondition (> (n) 0) :effect (scale-up (n) 2)))
)";
  auto t = ground(dom, "(define (problem g) (:domain grow) (:init (= (n) 20000)) (:goal (> (n) 30000)))");
  const State s = t->initial_state();
  const std::string e = error_of([&] { t->apply(s, 0); });
  EXPECT_TRUE(has(e, "(n)")) << e;
  EXPECT_TRUE(has(e, "40000")) << e;
  EXPECT_TRUE(has(e, "16-bit")) << e;
  // A comparison no state's value could decide.
  const std::string g = error_of([&] { t->compile_text("(> (n) 1000000)", "--goal"); });
  EXPECT_TRUE(has(g, "--goal:1:1")) << g;
  EXPECT_TRUE(has(g, "1000000")) << g;
}

TEST(Fluents, DivisionByZeroInAStateIsALocatedError) {
  const char* dom = R"((define (domain div) (:requirements :numeric-fluents)
  (:functions (a) (b))
  (:action dec :parameters () :precondition (> (b) 0) :effect (decrease (b) 1))
  (:action split :parameters ()
    :precondition (> (/ (a) (b)) 1) :effect (assign (a) 0)))
)";
  auto t = ground(dom, "(define (problem q) (:domain div) (:init (= (a) 4) (= (b) 1)) (:goal (= (a) 0)))");
  State s = t->apply(t->initial_state(), *t->find_action("(dec)"));
  const std::string e = error_of([&] { t->applicable_actions(s); });
  EXPECT_TRUE(has(e, "d.pddl:5:")) << e;
  EXPECT_TRUE(has(e, "division by zero")) << e;
}

TEST(Goals, AContradictionIsFalseAtOnce) {
  auto t = ground(kCounter, counter_problem(""));
  EXPECT_TRUE(t->compile_text("(and (done) (not (done)))").is_const_false());
  EXPECT_TRUE(t->compile_text("(or (done) (not (done)))").is_const_true());
}

TEST(Quantifiers, ExpansionsBeyondTheLimitAreRefusedQuickly) {
  // 16 nested foralls over 4 objects: 4^16 instances.
  std::string goal = "(done)";
  for (int i = 0; i < 16; ++i) goal = "(forall (?v" + std::to_string(i) + ") (or (done) " + goal + "))";
  const char* dom = R"((define (domain q) (:requirements :adl) (:predicates (done) (p ?x))
  (:action go :parameters () :precondition (and) :effect (done))))";
  auto t = ground(dom, "(define (problem q) (:domain q) (:objects a b c d) (:init) (:goal (done)))");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string e = error_of([&] { t->compile_text("(not " + goal + ")", "--goal"); });
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
  EXPECT_TRUE(has(e, "--goal:1:")) << e;
  EXPECT_TRUE(has(e, "--max-ground-actions")) << e;
}

// ---------------------------------------------------------------- derived predicates

// A line of rooms with doors; (reachable ?r) holds where the robot can walk
// through open doors; (sealed ?r) is a second stratum (not reachable).
const char* kRooms = R"((define (domain rooms)
  (:requirements :adl :derived-predicates)
  (:types room)
  (:predicates (at ?r - room) (door ?a ?b - room) (open ?a ?b - room)
               (reachable ?r - room) (sealed ?r - room))
  (:derived (reachable ?r - room)
    (or (at ?r) (exists (?s - room) (and (reachable ?s) (door ?s ?r) (open ?s ?r)))))
  (:derived (sealed ?r) (not (reachable ?r)))
  (:action unlock :parameters (?a ?b - room)
    :precondition (and (reachable ?a) (door ?a ?b) (not (open ?a ?b)))
    :effect (open ?a ?b)))
)";
const char* kRoomsProblem = R"((define (problem r) (:domain rooms)
  (:objects r1 r2 r3 r4 - room)
  (:init (at r1) (door r1 r2) (door r2 r3) (door r3 r4) (open r1 r2))
  (:goal (and (reachable r4)))))";

TEST(Derived, AtomsFollowFromTheStateInStrata) {
  auto t = ground(kRooms, kRoomsProblem);
  EXPECT_GT(t->num_axioms(), 0);
  State s = t->initial_state();
  auto holds = [&](const std::string& a, const std::string& r) { return t->test(s, t->atom(a, {r})); };
  EXPECT_TRUE(holds("reachable", "r1"));
  EXPECT_TRUE(holds("reachable", "r2"));
  EXPECT_FALSE(holds("reachable", "r3"));
  EXPECT_TRUE(holds("sealed", "r3"));
  EXPECT_TRUE(t->is_derived(t->atom("sealed", {"r4"}).bit));
  // Actions read them: only r2's door can be unlocked now; after it, r3 is reachable.
  ASSERT_EQ(t->applicable_actions(s).size(), 1u);
  s = t->apply(s, *t->find_action("(unlock r2 r3)"));
  EXPECT_TRUE(holds("reachable", "r3"));
  EXPECT_FALSE(holds("sealed", "r3"));
  EXPECT_TRUE(holds("sealed", "r4"));
  // And plans through them (simulate checks every step's precondition).
  const auto run = simulate(*t, t->initial_state(), parse_plan("(unlock r2 r3)\n(unlock r3 r4)\n", "plan"));
  EXPECT_TRUE(t->compile_text("(reachable r4)").holds(run.states.back()));
}

TEST(Derived, EffectsInitAndNegativeCyclesAreRefused) {
  std::string dom = kRooms;
  std::string e = error_of([&] {
    std::string bad = dom;
    bad.replace(bad.find(":effect (open ?a ?b)"), 20, ":effect (reachable ?b)");
    parse_domain(bad, "d.pddl");
  });
  EXPECT_TRUE(has(e, "d.pddl:11:")) << e;
  EXPECT_TRUE(has(e, "derived")) << e;
  e = error_of([&] {
    std::string prob = kRoomsProblem;
    prob.replace(prob.find("(at r1)"), 7, "(at r1) (reachable r4)");
    parse(kRooms, prob);
  });
  EXPECT_TRUE(has(e, "p.pddl:3:")) << e;
  EXPECT_TRUE(has(e, "derived")) << e;
  e = error_of([&] {
    std::string cyc = dom;
    cyc.replace(cyc.find("(or (at ?r)"), 11, "(or (sealed ?r)");
    ground(cyc, kRoomsProblem);
  });
  EXPECT_TRUE(has(e, "d.pddl:")) << e;
  EXPECT_TRUE(has(e, "stratified")) << e;
}

// ---------------------------------------------------------------- reachability

// A ring of n places: (go ?a ?b) has n x n parameter tuples, n reachable ones.
std::string ring_problem(int n) {
  std::string objs, init = "(at p0)";
  for (int i = 0; i < n; ++i) {
    objs += " p" + std::to_string(i);
    init += " (next p" + std::to_string(i) + " p" + std::to_string((i + 1) % n) + ")";
  }
  return "(define (problem ring) (:domain ring) (:objects" + objs + ") (:init " + init + ") (:goal (at p1)))";
}
const char* kRing = R"((define (domain ring) (:requirements :strips)
  (:predicates (at ?x) (next ?x ?y) (far ?x))
  (:action go :parameters (?a ?b) :precondition (and (at ?a) (next ?a ?b)) :effect (and (not (at ?a)) (at ?b)))
  (:action leap :parameters (?a ?b) :precondition (and (at ?a) (far ?b)) :effect (and (not (at ?a)) (at ?b))))
)";

TEST(Reachability, OnlyReachableActionsAreGroundedAndTheLimitCountsThem) {
  // 1500 x 1500 = 2.25 million tuples per schema, beyond the default limit:
  // 1500 are reachable (no place is ever far).
  auto t = ground(kRing, ring_problem(1500));
  EXPECT_EQ(t->num_actions(), 1500);
  EXPECT_FALSE(t->find_action("(leap p0 p2)"));
  EXPECT_FALSE(t->find_action("(go p0 p2)"));
  // The limit names the real count.
  GroundingOptions o;
  o.max_ground_actions = 1000;
  const std::string e = error_of([&] { ground(kRing, ring_problem(1500), o); });
  EXPECT_TRUE(has(e, "more than 1000 ground actions are reachable")) << e;
  EXPECT_TRUE(has(e, "action 'go' 1001")) << e;
  EXPECT_TRUE(has(e, "d.pddl:3:")) << e;
  EXPECT_TRUE(has(e, "--max-ground-actions")) << e;
}

TEST(Reachability, UndefinedFluentsAreFineWhereNoReachableActionReadsThem) {
  const char* dom = R"((define (domain lift) (:requirements :typing :action-costs)
  (:types floor)
  (:predicates (at ?f - floor) (serves ?f - floor))
  (:functions (total-cost) (time ?a ?b - floor))
  (:action move :parameters (?a ?b - floor) :precondition (and (at ?a) (serves ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (time ?a ?b)))))
)";
  // f3 is never served: (time f1 f3) and (time f3 ...) are never read.
  auto t = ground(dom, R"((define (problem l) (:domain lift) (:objects f1 f2 f3 - floor)
    (:init (at f1) (serves f1) (serves f2) (= (time f1 f2) 3) (= (time f2 f1) 3) (= (time f1 f1) 1) (= (time f2 f2) 1)
           (= (total-cost) 0)) (:goal (at f2))))");
  EXPECT_EQ(t->num_actions(), 4);
  EXPECT_EQ(t->action(*t->find_action("(move f1 f2)")).cost, 3);
  // Read by a reachable action: a located error naming the fluent.
  const std::string e = error_of([&] {
    ground(dom, R"((define (problem l) (:domain lift) (:objects f1 f2 - floor)
      (:init (at f1) (serves f1) (serves f2) (= (time f1 f2) 3) (= (total-cost) 0)) (:goal (at f2))))");
  });
  EXPECT_TRUE(has(e, "d.pddl:6:")) << e;
  EXPECT_TRUE(has(e, "(time f1 f1)")) << e;
}

}  // namespace
