#include "pddl/limits_test.hpp"

namespace limits_test {
TEST(GroundingLimit, ATaskBeyondTheLimitIsRefusedNamingTheActionAndTheCount) {
  // 60 x 60 x 60 = 216,000 reachable ground actions against a limit of
  // 100,000: refused once reachability has found that many, naming the
  // action with the most, its location and the count.
  std::string e = error_of([&] { ground_links(60, 60, 100000); });
  EXPECT_TRUE(has(e, "links.pddl:5:")) << e;
  EXPECT_TRUE(has(e, "action 'link' 100001")) << e;
  EXPECT_TRUE(has(e, "more than 100000 ground actions are reachable")) << e;
  EXPECT_TRUE(has(e, "--max-ground-actions")) << e;
}

TEST(GroundingLimit, LimitIsAnOptionAndCountsStaticPruning) {
  // 6 objects, 2 rooms: 6 x 6 x 2 = 72 reachable actions (not 216).
  EXPECT_TRUE(has(error_of([&] { ground_links(6, 2, 71); }), "more than 71 ground actions are reachable")) << "limit 71";
  auto t = ground_links(6, 2, 72);
  EXPECT_EQ(t->num_actions(), 72);
  // Raising the limit grounds what the default refuses to.
  EXPECT_EQ(ground_links(6, 6, 216)->num_actions(), 216);
  EXPECT_FALSE(error_of([&] { ground_links(6, 6, 215); }).empty());
}

TEST(ReaderLimit, TopLevelAtomsAndTrailingTextStopAtOnce) {
  std::string tail(100000, 'y');
  std::string e = error_of([&] { parse_domain("x " + tail, "atoms.pddl"); });
  EXPECT_TRUE(has(e, "atoms.pddl:1:1:")) << e;
  e = error_of([&] { parse_domain("(define (domain d))\n  (" + tail + ")", "two.pddl"); });
  EXPECT_TRUE(has(e, "two.pddl:2:3:")) << e;
  EXPECT_TRUE(has(e, "after the end")) << e;
}

TEST(ActionCosts, NegativeCostIsALocatedError) {
  const char* dom = R"((define (domain c) (:requirements :strips :action-costs)
  (:predicates (done))
  (:functions (total-cost) - number)
  (:action go :parameters ()
    :precondition (not (done))
    :effect (and (done) (increase (total-cost) -3))))
)";
  auto d = std::make_shared<Domain>(parse_domain(dom, "c.pddl"));
  auto p = std::make_shared<Problem>(
      parse_problem(*d, "(define (problem q) (:domain c) (:init (= (total-cost) 0)) (:goal (done)))", "q.pddl"));
  std::string e = error_of([&] { Task t(d, p); });
  EXPECT_TRUE(has(e, "c.pddl:6:")) << e;
  EXPECT_TRUE(has(e, "(go)")) << e;
  EXPECT_TRUE(has(e, "negative cost (-3)")) << e;
}

TEST(Parameters, DuplicateNamesAreLocatedParseErrors) {
  const std::string dom = R"((define (domain dup) (:requirements :strips :typing :existential-preconditions)
  (:types t)
  (:predicates (p ?a ?b - t))
  (:action a :parameters (?x ?y - t ?x - t)
    :precondition (p ?x ?y) :effect (not (p ?x ?y))))
)";
  std::string e = error_of([&] { parse_domain(dom, "dup.pddl"); });
  EXPECT_TRUE(has(e, "dup.pddl:4:")) << e;
  EXPECT_TRUE(has(e, "'?x'")) << e;
  EXPECT_TRUE(has(e, "declared twice")) << e;
  // In a quantifier's list too.
  std::string q = dom;
  q.replace(q.find("(?x ?y - t ?x - t)"), 18, "(?x - t)");
  q.replace(q.find(":precondition (p ?x ?y)"), 23, ":precondition (exists (?y ?y - t) (p ?x ?y))");
  q.replace(q.find("(not (p ?x ?y))"), 15, "(not (p ?x ?x))");
  e = error_of([&] { parse_domain(q, "dupq.pddl"); });
  EXPECT_TRUE(has(e, "dupq.pddl:5:")) << e;
  EXPECT_TRUE(has(e, "declared twice")) << e;
}

}  // namespace limits_test
