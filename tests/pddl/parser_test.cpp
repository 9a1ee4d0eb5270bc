#include "pddl/parser_test.hpp"

TEST(Parser, ReadsTheProjectsDoorsKeysGemsDomain) {
  Domain d = load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl");
  EXPECT_EQ(d.name, "doors-keys-gems");
  EXPECT_EQ(d.actions.size(), 8u);
  EXPECT_EQ(d.actions[0].name, "pickup");
  auto key = d.find_type("key"), physical = d.find_type("physical"), agent = d.find_type("agent");
  ASSERT_TRUE(key && physical && agent);
  EXPECT_TRUE(d.is_subtype(*key, *physical));
  EXPECT_FALSE(d.is_subtype(*key, *agent));
  auto walls = d.find_function("walls");
  ASSERT_TRUE(walls);
  EXPECT_EQ(d.functions[*walls].type, ValueType::Matrix);
}

TEST(Parser, IsCaseInsensitiveAndSkipsComments) {
  const char* text = R"(; leading comment
(DEFINE (Domain Mini)   ; trailing
  (:Requirements :TYPING)
  (:TYPES Box)
  (:Predicates (Full ?B - BOX))
  (:Action Fill :Parameters (?b - box) :Precondition (NOT (full ?B)) :Effect (FULL ?b)))
)";
  Domain d = parse_domain(text, "mini.pddl");
  EXPECT_EQ(d.name, "mini");
  ASSERT_EQ(d.actions.size(), 1u);
  EXPECT_EQ(d.actions[0].name, "fill");
}

TEST(ParserErrors, UnbalancedParenthesesNamesTheOpeningLine) {
  std::string e = error_of([] { parse_domain("(define (domain x)\n  (:predicates (p)\n", "bad.pddl"); });
  EXPECT_NE(e.find("bad.pddl:2:3"), std::string::npos) << e;
  EXPECT_NE(e.find("unbalanced parentheses"), std::string::npos) << e;
  e = error_of([] { parse_domain("(define (domain x)))", "bad2.pddl"); });
  EXPECT_NE(e.find("bad2.pddl:1:20"), std::string::npos) << e;
}

TEST(ParserErrors, UnsupportedRequirement) {
  std::string e = error_of([] { parse_domain("(define (domain x)\n (:requirements :strips :durative-actions))", "r.pddl"); });
  EXPECT_NE(e.find("r.pddl:2:25"), std::string::npos) << e;
  EXPECT_NE(e.find("unsupported requirement ':durative-actions'"), std::string::npos) << e;
}

TEST(ParserErrors, UnknownType) {
  std::string e = error_of([] {
    parse_domain("(define (domain x) (:types a)\n (:predicates (p ?v - banana)))", "t.pddl");
  });
  EXPECT_NE(e.find("t.pddl:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown type 'banana'"), std::string::npos) << e;
}

TEST(ParserErrors, UnknownPredicateInAction) {
  std::string e = error_of([] {
    parse_domain(
        "(define (domain x) (:predicates (p))\n (:action a :parameters () :precondition (q) :effect (p)))", "u.pddl");
  });
  EXPECT_NE(e.find("u.pddl:2:42"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown predicate 'q'"), std::string::npos) << e;
}

TEST(ParserErrors, ArityMismatch) {
  std::string e = error_of([] {
    parse_domain("(define (domain x) (:predicates (p ?a ?b))\n (:action a :parameters (?x) :precondition (p ?x) :effect (p ?x ?x)))",
                 "a.pddl");
  });
  EXPECT_NE(e.find("a.pddl:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("arity mismatch: predicate 'p' takes 2 argument(s), given 1"), std::string::npos) << e;
}

TEST(ParserErrors, UnknownVariableAndObject) {
  std::string e = error_of([] {
    parse_domain("(define (domain x) (:predicates (p ?a))\n (:action a :parameters (?x) :precondition (p ?y) :effect (p ?x)))", "v.pddl");
  });
  EXPECT_NE(e.find("unknown variable '?y'"), std::string::npos) << e;
  Domain d = parse_domain(kMiniDomain, "mini.pddl");
  e = error_of([&] {
    parse_problem(d, "(define (problem p) (:domain mini) (:objects b1 - box l1 - place)\n (:init (at b2 l1)) (:goal (at b1 l1)))", "p.pddl");
  });
  EXPECT_NE(e.find("p.pddl:2:13"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown object 'b2'"), std::string::npos) << e;
}

TEST(ParserErrors, TypeMismatchOfAnObject) {
  Domain d = parse_domain(kMiniDomain, "mini.pddl");
  std::string e = error_of([&] {
    parse_problem(d, "(define (problem p) (:domain mini) (:objects b1 - box l1 - place)\n (:init (at l1 l1)) (:goal (at b1 l1)))", "p.pddl");
  });
  EXPECT_NE(e.find("type mismatch"), std::string::npos) << e;
  EXPECT_NE(e.find("expected box, got place"), std::string::npos) << e;
}

TEST(ParserErrors, ProblemForAnotherDomain) {
  Domain d = parse_domain(kMiniDomain, "mini.pddl");
  std::string e = error_of([&] { parse_problem(d, "(define (problem p) (:domain other) (:objects) (:init))", "p.pddl"); });
  EXPECT_NE(e.find("domain 'other'"), std::string::npos) << e;
}

TEST(ParserErrors, DuplicateObject) {
  Domain d = parse_domain(kMiniDomain, "mini.pddl");
  std::string e = error_of([&] { parse_problem(d, "(define (problem p) (:domain mini) (:objects b1 b1 - box) (:init))", "p.pddl"); });
  EXPECT_NE(e.find("object 'b1' declared twice"), std::string::npos) << e;
}

TEST(ParserErrors, GarbageFileIsRejectedWithLocation) {
  std::string e = error_of([] { parse_domain("hello world", "g.pddl"); });
  EXPECT_NE(e.find("g.pddl:1:1"), std::string::npos) << e;
  e = error_of([] { load_domain("/nonexistent/domain.pddl"); });
  EXPECT_NE(e.find("/nonexistent/domain.pddl: cannot open file"), std::string::npos) << e;
}

TEST(Printing, ConditionsRoundTripWithBindings) {
  Domain d = load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl");
  Problem p = parse_problem(d, R"((define (problem t) (:domain doors-keys-gems)
      (:objects key1 - key door1 - door red - color human - human robot - robot)
      (:init (= (walls) (new-bit-matrix false 2 2)))
      (:goal (exists (?k - key) (and (has human ?k) (iscolor ?k red))))))", "t.pddl");
  std::vector<std::string> names;
  EXPECT_EQ(to_pddl(d, p, *p.goal, names), "(exists (?k - key) (and (has human ?k) (iscolor ?k red)))");
}
