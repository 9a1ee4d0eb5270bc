#pragma once
// The includes, helpers and fixtures of the language tests in listen_cli_test.cpp, shared by
// the files of that name in tests/language/ and its label folders
// (docs/testing.md, "Labels").
// `clips listen` and `clips lm-score` through the built binary.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_paths.hpp"

namespace listen_cli_test {

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

}  // namespace listen_cli_test
using namespace listen_cli_test;
