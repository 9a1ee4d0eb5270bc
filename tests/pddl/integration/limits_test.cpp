#include "pddl/limits_test.hpp"

namespace limits_test {
TEST(ReaderLimit, HugeFileOfRepeatedTokensFailsFast) {
  std::string text = "(define (domain d)";
  for (long i = 0; i <= kMaxTokens; ++i) text += " x";
  text += ")";
  std::string e = error_of([&] { parse_domain(text, "huge.pddl"); });
  EXPECT_TRUE(has(e, "huge.pddl:1:")) << e;
  EXPECT_TRUE(has(e, "tokens")) << e;
}

}  // namespace limits_test
