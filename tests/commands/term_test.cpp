#include "commands/term.hpp"

#include <gtest/gtest.h>

namespace clips::commands {
namespace {

TEST(Term, ParsesAndPrintsPddlForm) {
  const Term t = parse_term("( handover  robot human key2 )");
  EXPECT_EQ(t.name, "handover");
  EXPECT_EQ(t.args, (std::vector<std::string>{"robot", "human", "key2"}));
  EXPECT_EQ(to_pddl(t), "(handover robot human key2)");
}

TEST(Term, ParsesSequencesAndVariables) {
  const auto ts = parse_terms("(pickup you ?key1)\n(iscolor ?key1 red)");
  ASSERT_EQ(ts.size(), 2u);
  EXPECT_TRUE(is_variable(ts[0].args[1]));
  EXPECT_FALSE(is_variable(ts[0].args[0]));
  EXPECT_EQ(to_pddl(ts), "(pickup you ?key1) (iscolor ?key1 red)");
  EXPECT_EQ(to_pddl(parse_term("(wait)")), "(wait)");
}

TEST(Term, RejectsMalformedText) {
  EXPECT_THROW(parse_term("(pickup robot key1"), std::invalid_argument);
  EXPECT_THROW(parse_term("pickup robot"), std::invalid_argument);
  EXPECT_THROW(parse_term("()"), std::invalid_argument);
  EXPECT_THROW(parse_term("(a (b c))"), std::invalid_argument);
  EXPECT_THROW(parse_term("(a) (b)"), std::invalid_argument);
}

}  // namespace
}  // namespace clips::commands
