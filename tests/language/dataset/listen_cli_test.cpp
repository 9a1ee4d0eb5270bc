#include "language/listen_cli_test.hpp"

namespace listen_cli_test {
TEST_F(ListenCli, JsonShape) {
  const CliRun r = run("listen " + dataset() + " --plan 2.1.keys --json --top 5");
  ASSERT_EQ(r.status, 0) << r.out;
  // Exactly one JSON object on stdout.
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 3u);  // utterance, readable_share, commands (no warning: every word is readable)
  EXPECT_EQ(j.at("utterance"), "Can you pass me the red key?");  // the literal utterance file
  EXPECT_EQ(j.at("readable_share"), 1.0);
  const auto& cmds = j.at("commands");
  ASSERT_TRUE(cmds.is_array());
  ASSERT_EQ(cmds.size(), 5u);
  double previous = 1.0;
  for (const auto& c : cmds) {
    ASSERT_TRUE(c.is_object());
    EXPECT_EQ(c.size(), 2u);
    ASSERT_TRUE(c.at("command").is_string());
    ASSERT_TRUE(c.at("prob").is_number());
    EXPECT_EQ(c.at("command").get<std::string>().rfind("(", 0), 0u);
    const double p = c.at("prob").get<double>();
    EXPECT_GE(p, 0.0);
    EXPECT_LE(p, previous);
    previous = p;
  }
  // Display form: variables keep their '?'.
  EXPECT_NE(cmds[0].at("command").get<std::string>().find("?key1"), std::string::npos);
}

// As `clips infer` warns: words the model mostly cannot read give a ranking
// near the prior, and listen says so (stderr, and "warning" in --json).
TEST_F(ListenCli, UnreadableUtteranceIsFlagged) {
  const CliRun r = run("listen " + dataset() + " --plan 2.1.keys --json --top 3 --utterance '?!?! ... ?'");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("readable_share"), 0.0);
  EXPECT_NE(j.value("warning", "").find("can read 0% of the utterance's words"), std::string::npos) << r.out;
  const CliRun table = run("listen " + dataset() + " --plan 2.1.keys --top 3 --utterance 'Kannst du mir den roten Schlüssel geben?'", true);
  EXPECT_NE(table.out.find("warning: the language model can read"), std::string::npos) << table.out;
}

TEST_F(ListenCli, AllCommandsSumToOne) {
  const CliRun r = run("listen " + dataset() + " --plan 1.1.keys --utterance 'Can you open the red door?' --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("utterance"), "Can you open the red door?");
  EXPECT_EQ(j.at("commands").size(), 26u);  // problem 1, see listener_test.cpp
  double total = 0;
  for (const auto& c : j.at("commands")) total += c.at("prob").get<double>();
  EXPECT_NEAR(total, 1.0, 1e-9);
}

TEST_F(ListenCli, BlankUtteranceExitsTwo) {
  const CliRun r = run("listen " + dataset() + " --plan 2.1.keys --utterance '   '", true);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--utterance is empty"), std::string::npos) << r.out;
}

TEST_F(ListenCli, TableOutput) {
  const CliRun r = run("listen " + dataset() + " --plan 13.1.doors --top 3");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("Can you open the blue door?"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rank"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("more; use --top"), std::string::npos) << r.out;
}

}  // namespace listen_cli_test
