// The bench's per-category table: every name printed whole, in its own column.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "eval/breakdown.hpp"

namespace clips::eval {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(BreakdownTable, LongCategoryAndMethodNamesKeepTheirColumns) {
  Breakdown b;
  CategoryRow longest;
  longest.category = "request-self-doable";
  longest.n = 2;
  longest.p_true_goal = {{"observer_only", 0.75}, {"clips", 0.5}};
  longest.precision = {{"listener_only", 0.25}};
  CategoryRow short_one;
  short_one.category = "goal";
  short_one.split = "dev";
  short_one.n = 12;
  short_one.p_true_goal = {{"clips", 0.35}};
  b.categories = {longest, short_one};
  const std::vector<std::string> lines = lines_of(breakdown_table(b));

  size_t head = lines.size();
  for (size_t i = 0; i < lines.size(); ++i)
    if (lines[i].rfind("category", 0) == 0) head = i;
  ASSERT_LT(head + 2, lines.size()) << breakdown_table(b);
  const std::string& h = lines[head];
  // Method names whole in the header (they were cut to 10 and 7 characters).
  EXPECT_NE(h.find("P observer_only"), std::string::npos) << h;
  EXPECT_NE(h.find("prec listener_only"), std::string::npos) << h;
  // The split column starts at the same place on every line, after a space.
  const size_t split_col = h.find("split");
  ASSERT_NE(split_col, std::string::npos);
  EXPECT_EQ(lines[head + 1].rfind("request-self-doable", 0), 0u);
  EXPECT_EQ(lines[head + 1].substr(split_col, 3), "all") << lines[head + 1];
  EXPECT_EQ(lines[head + 1][split_col - 1], ' ');
  EXPECT_EQ(lines[head + 2].substr(split_col, 3), "dev") << lines[head + 2];
  // Values end where their header ends.
  const size_t p_action_end = h.find("P observer_only") + std::string("P observer_only").size();
  EXPECT_EQ(lines[head + 1].substr(p_action_end - 4, 4), "0.75") << lines[head + 1];
  // A method without a value on a row is a dash.
  EXPECT_NE(lines[head + 2].find("–"), std::string::npos) << lines[head + 2];
}

}  // namespace
}  // namespace clips::eval
