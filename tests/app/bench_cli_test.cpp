#include "app/bench_cli_test.hpp"

namespace clips::eval {
namespace bench_cli_test {
// Item 2: the failure row had 16 fields against the header's 15.
TEST(BenchCsv, EveryRowHasTheHeadersFieldCount) {
  const auto rows = parse_csv(results_csv(report_with_failures()));
  ASSERT_EQ(rows.size(), 4u);
  const auto& header = rows[0];
  EXPECT_EQ(header.size(), 18u);
  EXPECT_EQ(header[15], "domain");
  EXPECT_EQ(header[16], "requested");
  EXPECT_EQ(header.back(), "request_done");
  for (const auto& row : rows) EXPECT_EQ(row.size(), header.size()) << row[0];
  const auto& fail = rows[3];
  EXPECT_EQ(fail[0], "2.1.keys");
  EXPECT_EQ(fail[column(header, "seconds")], "0.077");
  EXPECT_EQ(fail[column(header, "options")], "");
  EXPECT_EQ(fail[column(header, "error")], "reply from the language model: \"oops\", status 500");
  EXPECT_TRUE(contains(rows[2][column(header, "error")], "second line"));
}

TEST(BenchTable, FailedPlansDoNotPointToAMissingCsv) {
  const std::string table = results_table(report_with_failures(), "/nonexistent.json");
  EXPECT_TRUE(contains(table, "1 plan(s) failed")) << table;
  EXPECT_TRUE(contains(table, "2.1.keys")) << table;
  EXPECT_FALSE(contains(table, "results.csv")) << table;
}

}  // namespace bench_cli_test

}  // namespace clips::eval
