// Hostile input (found by fuzzing the CLI): deep nesting, huge integers,
// byte-order marks and control bytes give located errors, never a crash, a
// bare library exception or a location that points nowhere.
#include <gtest/gtest.h>

#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "pddl/support.hpp"
#include "test_paths.hpp"

using namespace clips;
using namespace clips::pddl;

namespace {

using clips::pddl::testing::error_of;

size_t count_of(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

std::string nested(const std::string& open, const std::string& inner, int depth) {
  std::string s;
  for (int i = 0; i < depth; ++i) s += open;
  s += inner;
  return s + std::string(depth, ')');
}

std::string examples(const std::string& file) { return read_text_file(paths::examples_dir() + "/" + file); }

std::shared_ptr<Domain> blocks_domain() {
  return std::make_shared<Domain>(parse_domain(examples("blocks/domain.pddl"), "domain.pddl"));
}

// The blocks problem with `from` replaced by `to`.
std::string blocks_problem(const std::string& from, const std::string& to) {
  std::string p = examples("blocks/p1.pddl");
  size_t at = p.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return p.replace(at, from.size(), to);
}

const char* kDomainHead = R"((define (domain deep)
  (:predicates (p))
  (:action a :parameters ()
   :precondition )";

}  // namespace

TEST(Nesting, DeepDomainIsALocatedErrorNotACrash) {
  std::string text = std::string(kDomainHead) + nested("(and ", "(p)", 100000) + " :effect (p)))";
  std::string e = error_of([&] { parse_domain(text, "deep.pddl"); });
  // 1000 levels are allowed: (define, (:action, then 998 (and; the next one is too deep.
  EXPECT_NE(e.find("deep.pddl:4:" + std::to_string(18 + 998 * 5)), std::string::npos) << e.substr(0, 200);
  EXPECT_NE(e.find("nesting deeper than 1000 levels"), std::string::npos) << e.substr(0, 200);
}

TEST(Nesting, DeepProblemGoalAndPlanLineAreLocatedErrors) {
  auto d = blocks_domain();
  std::string e = error_of([&] {
    parse_problem(*d, blocks_problem("(and (on a b) (on b c))", nested("(not ", "(on a b)", 50000)), "p.pddl");
  });
  EXPECT_NE(e.find("p.pddl:5:"), std::string::npos) << e.substr(0, 200);
  EXPECT_NE(e.find("nesting deeper than 1000 levels"), std::string::npos) << e.substr(0, 200);

  auto p = std::make_shared<Problem>(parse_problem(*d, examples("blocks/p1.pddl"), "p.pddl"));
  Task t(d, p);
  e = error_of([&] { simulate(t, t.initial_state(), parse_plan("(pick b a)\n" + nested("(", "x", 100000), "plan")); });
  EXPECT_NE(e.find("plan:2:1001: malformed action"), std::string::npos) << e.substr(0, 200);
  EXPECT_NE(e.find("nesting deeper than 1000 levels"), std::string::npos) << e.substr(0, 300);
  EXPECT_LT(e.size(), 400u);  // the quoted line is cut short
}

TEST(Nesting, ConditionsUpToTheLimitParseAndGround) {
  // 990 nested (and ...) around (p): parsing, grounding and printing recurse
  // that deep without trouble.
  std::string text = std::string(kDomainHead) + nested("(and ", "(not (p))", 990) + " :effect (p)))";
  auto d = std::make_shared<Domain>(parse_domain(text, "ok.pddl"));
  auto p = std::make_shared<Problem>(parse_problem(*d, "(define (problem q) (:domain deep) (:init) (:goal (p)))", "q"));
  Task t(d, p);
  ASSERT_EQ(t.num_actions(), 1);
  EXPECT_TRUE(t.applicable(0, t.initial_state().data()));
  EXPECT_EQ(to_pddl(*d, *p, *d->actions[0].precondition, {}).size(), 990 * 6 + 9);
}

TEST(Nesting, ExpressionsBuiltInCodeAreCheckedToo) {
  auto d = blocks_domain();
  Problem p = parse_problem(*d, examples("blocks/p1.pddl"), "p.pddl");
  SExpr e = read_one_sexpr("(on a b)", "<goal>");
  for (int i = 0; i < 1200; ++i) {
    SExpr wrap;
    wrap.is_list = true;
    wrap.loc = SourceLoc{"<built>", 1, 1};
    wrap.items.push_back(read_one_sexpr("not", "<built>"));
    wrap.items.push_back(std::move(e));
    e = std::move(wrap);
  }
  std::string err = error_of([&] { parse_condition(*d, p, e, nullptr); });
  EXPECT_NE(err.find("<built>:1:1: nesting deeper than 1000 levels"), std::string::npos) << err;
}

TEST(Integers, TooLargeLiteralNamesItsPositionAndTheRange) {
  auto d = blocks_domain();
  std::string e = error_of([&] {
    parse_problem(*d, blocks_problem("(= (moves) 0)", "(= (moves) 99999999999999999999)"), "p.pddl");
  });
  EXPECT_NE(e.find("p.pddl:4:43: integer 99999999999999999999 is out of range"), std::string::npos) << e;
  EXPECT_NE(e.find("between -9223372036854775808 and 9223372036854775807"), std::string::npos) << e;

  // The same in a goal given as text, e.g. on the command line.
  auto p = std::make_shared<Problem>(parse_problem(*d, examples("blocks/p1.pddl"), "p.pddl"));
  Task t(d, p);
  e = error_of([&] { t.compile_text("(= (moves) -99999999999999999999)", "<goal>"); });
  EXPECT_NE(e.find("<goal>:1:12: integer -99999999999999999999 is out of range"), std::string::npos) << e;
  // The extremes themselves are fine.
  EXPECT_NO_THROW(t.compile_text("(< (moves) 9223372036854775807)", "<goal>"));
}

TEST(Integers, OverflowInInitialArithmeticIsALocatedError) {
  auto d = blocks_domain();
  auto p = std::make_shared<Problem>(parse_problem(
      *d, blocks_problem("(= (moves) 0)", "(= (moves) (* 9223372036854775807 2))"), "p.pddl"));
  std::string e = error_of([&] { Task t(d, p); });
  EXPECT_NE(e.find("p.pddl:4:43: integer overflow"), std::string::npos) << e;
}

TEST(Integers, StateFluentOutOfInt16NamesTheValueAndTheRange) {
  auto d = blocks_domain();
  auto p = std::make_shared<Problem>(
      parse_problem(*d, blocks_problem("(= (moves) 0)", "(= (moves) 40000)"), "p.pddl"));
  std::string e = error_of([&] { Task t(d, p); });
  EXPECT_NE(e.find("p.pddl:4:43: fluent (moves) value 40000 is out of range"), std::string::npos) << e;
  EXPECT_NE(e.find("between -32768 and 32767"), std::string::npos) << e;
  // A fluent no action changes is folded and may hold a large value.
  auto p2 = std::make_shared<Problem>(
      parse_problem(*d, blocks_problem("(= (total-cost) 0)", "(= (total-cost) 40000)"), "p.pddl"));
  EXPECT_NO_THROW(Task(d, p2));
}

TEST(Locations, ProblemGoalPassedBackAsTextNamesTheProblemFile) {
  auto d = blocks_domain();
  // Loaded without its goal (as dataset problems are), then compiled from text.
  auto p = std::make_shared<Problem>(
      parse_problem(*d, blocks_problem("(on b c)", "(on b gem9)"), "problems/2.pddl", false));
  Task t(d, p);
  std::string e = error_of([&] { t.compile_text(p->goal_sexpr->str(), "<goal>"); });
  EXPECT_NE(e.find("problems/2.pddl:5:30: unknown object 'gem9'"), std::string::npos) << e;
  EXPECT_EQ(e.find("<goal>"), std::string::npos) << e;
}

TEST(Locations, MalformedPlanLineHasOneLocation) {
  auto d = blocks_domain();
  auto p = std::make_shared<Problem>(parse_problem(*d, examples("blocks/p1.pddl"), "p.pddl"));
  Task t(d, p);
  auto err = [&](const std::string& plan) {
    return error_of([&] { simulate(t, t.initial_state(), parse_plan(plan, "plan.pddl")); });
  };
  std::string e = err("(pick b a)\n  (place b table) (x)\n");
  EXPECT_NE(e.find("plan.pddl:2:19: malformed action '(place b table) (x)': expected exactly one expression, found 2"),
            std::string::npos) << e;
  EXPECT_EQ(count_of(e, "plan.pddl"), 1u) << e;
  e = err("\n (pick b a\n");
  EXPECT_NE(e.find("plan.pddl:2:2: malformed action '(pick b a': unbalanced parentheses"), std::string::npos) << e;
  EXPECT_EQ(count_of(e, "plan.pddl"), 1u) << e;
  e = err("  (pick b d)\n");
  EXPECT_NE(e.find("plan.pddl:1:3: unknown object 'd'"), std::string::npos) << e;
}

TEST(Encoding, ByteOrderMarkIsSkipped) {
  auto d = std::make_shared<Domain>(parse_domain("\xEF\xBB\xBF" + examples("blocks/domain.pddl"), "domain.pddl"));
  auto p = std::make_shared<Problem>(parse_problem(*d, "\xEF\xBB\xBF" + examples("blocks/p1.pddl"), "p.pddl"));
  Task t(d, p);
  PlanFile plan = parse_plan("\xEF\xBB\xBF(pick b a)\n(place b table)\n", "plan.pddl");
  ASSERT_EQ(plan.actions.size(), 2u);
  EXPECT_EQ(plan.actions[0].loc.col, 1);
  EXPECT_EQ(simulate(t, t.initial_state(), plan).actions.size(), 2u);
  // Positions count from after the mark.
  std::string e = error_of([] { parse_domain("\xEF\xBB\xBF(define (domain x)))", "bom.pddl"); });
  EXPECT_NE(e.find("bom.pddl:1:20"), std::string::npos) << e;
}

TEST(Encoding, ControlBytesInInputAreEscapedInMessages) {
  std::string e = error_of([] {
    parse_domain(std::string("(define (domain x)\n (:predicates \x1b[2J") + '\0' + " (p)))", "ctl.pddl");
  });
  EXPECT_NE(e.find("ctl.pddl:2:15: expected a predicate declaration, found '\\x1b[2j\\x00'"), std::string::npos) << e;
  for (char c : e) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\t') << e;

  auto d = blocks_domain();
  auto p = std::make_shared<Problem>(parse_problem(*d, examples("blocks/p1.pddl"), "p.pddl"));
  Task t(d, p);
  e = error_of([&] { simulate(t, t.initial_state(), parse_plan("(pick b \x07\x1b)\n", "plan.pddl")); });
  EXPECT_NE(e.find("unknown object '\\x07\\x1b' in (pick b \\x07\\x1b)"), std::string::npos) << e;
}

TEST(Encoding, PrintableEscapesAndCuts) {
  EXPECT_EQ(printable("a\tb\nc\x7f"), "a\tb\\x0ac\\x7f");
  EXPECT_EQ(printable("abcdef", 3), "abc...");
  EXPECT_EQ(printable("ab\xC3\xA9", 3), "ab...");  // never half a UTF-8 character
  EXPECT_EQ(printable("caf\xC3\xA9"), "caf\xC3\xA9");
}
