#include "language/listen_cli_test.hpp"

namespace listen_cli_test {
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

}  // namespace listen_cli_test
