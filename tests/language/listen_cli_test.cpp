// `clips listen` and `clips lm-score` through the built binary.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_paths.hpp"

namespace {

const std::string kBinary = std::string(CLIPS_BINARY_DIR) + "/clips";

struct CliRun {
  int status = -1;
  std::string out;  // stdout and stderr together
};

CliRun run(const std::string& args, bool merge_stderr = false) {
  const std::string cmd = "'" + kBinary + "' " + args + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  CliRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

class ListenCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << "no binary " << kBinary;
    if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "no dataset at " << clips::paths::dkg_dataset();
  }
  std::string dataset() const { return "--dataset '" + clips::paths::dkg_dataset() + "'"; }
};

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

TEST_F(ListenCli, LmScorePrintsLogProbAndBackend) {
  const auto prompt = std::filesystem::temp_directory_path() / "clips-lm-score-test-prompt.txt";
  {
    FILE* f = std::fopen(prompt.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("Input: (pickup you key1) where (iscolor key1 yellow)\nOutput: Please pick up the yellow key.\n"
               "Input: (handover you me key1) where (iscolor key1 red)\nOutput:\n",
               f);
    std::fclose(f);
  }
  const CliRun r = run("lm-score --prompt-file '" + prompt.string() + "' --continuation 'Can you pass me the red key?'");
  std::filesystem::remove(prompt);
  ASSERT_EQ(r.status, 0) << r.out;
  double score = 0;
  char name[64] = {0};
  ASSERT_EQ(std::sscanf(r.out.c_str(), "%lf\t%63s", &score, name), 2) << r.out;
  EXPECT_LT(score, 0.0);
  EXPECT_NE(std::string(name).find("embedded"), std::string::npos);
}

TEST_F(ListenCli, LmScoreReadsWindowsLineEndingsAndRefusesNonPromptFiles) {
  const auto dir = std::filesystem::temp_directory_path() / "clips-lm-score-files";
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    FILE* f = std::fopen((dir / name).c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
    return "'" + (dir / name).string() + "'";
  };
  const std::string prompt =
      "Input: (pickup you key1) where (iscolor key1 yellow)\nOutput: Please pick up the yellow key.\n"
      "Input: (handover you me key1) where (iscolor key1 red)\nOutput:\n";
  std::string crlf;
  for (char c : prompt) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const std::string args = " --continuation 'Can you pass me the red key?'";
  const CliRun unix_run = run("lm-score --prompt-file " + write("unix.txt", prompt) + args);
  const CliRun windows_run = run("lm-score --prompt-file " + write("windows.txt", crlf) + args);
  ASSERT_EQ(unix_run.status, 0) << unix_run.out;
  EXPECT_EQ(windows_run.status, 0) << windows_run.out;
  EXPECT_EQ(windows_run.out, unix_run.out);

  const CliRun directory = run("lm-score --prompt-file '" + dir.string() + "'" + args, true);
  EXPECT_NE(directory.status, 0);
  EXPECT_NE(directory.out.find("is a directory"), std::string::npos) << directory.out;
  const CliRun huge = run("lm-score --prompt-file /dev/zero" + args, true);
  EXPECT_NE(huge.status, 0);
  EXPECT_NE(huge.out.find("larger than 16 MiB"), std::string::npos) << huge.out;
  const CliRun timeout = run("lm-score --prompt-file " + write("unix.txt", prompt) + args + " --lm-timeout nan", true);
  EXPECT_NE(timeout.status, 0);
  EXPECT_NE(timeout.out.find("--lm-timeout"), std::string::npos) << timeout.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
