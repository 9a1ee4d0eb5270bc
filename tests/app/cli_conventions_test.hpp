#pragma once
// The includes, helpers and fixtures of the app tests in cli_conventions_test.cpp, shared by
// the files of that name in tests/app/ and its label folders
// (docs/testing.md, "Labels").
// The command line's conventions: --version, documented exit statuses (one
// test per status that can be provoked from outside), results on stdout and
// "wrote ..." notes on stderr, bench's output files, ad-hoc observations for
// infer/assist, and the smaller checks of issue 21 (seed range, --out "",
// render's output names, a plan path that is a directory, $CLIPS_DATASET,
// --utterance's UTF-8).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/support.hpp"
#include "test_paths.hpp"

namespace clips::eval {
namespace cli_conventions_test {

namespace fs = std::filesystem;

// `clips infer --json` steps without their wall times, which differ run to run.
nlohmann::json untimed_steps(const std::string& out) {
  nlohmann::json steps = nlohmann::json::parse(out)["steps"];
  for (auto& st : steps) {
    EXPECT_TRUE(st.contains("seconds") && st["seconds"].is_number());
    st.erase("seconds");
  }
  return steps;
}

using testing::clips_binary;
using testing::contains;
using testing::examples_dkg;
using testing::run;

// stdout alone (stderr dropped), with the exit status.
testing::RunResult run_stdout(const std::string& command) {
  testing::RunResult r;
  FILE* p = popen((command + " 2>/dev/null").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::string clips() { return clips_binary() + " "; }
std::string dkg() { return " --dataset " + examples_dkg(); }
std::string sq(const std::string& s) { return "'" + s + "'"; }

// A copy of the repo's Doors-Keys-Gems examples that a test may break.
struct ExamplesCopy {
  testing::TempDir tmp{"examples"};
  fs::path dir = tmp.path / "dkg";
  ExamplesCopy() { fs::copy(examples_dkg(), dir, fs::copy_options::recursive); }
};

// --- version --------------------------------------------------------------

// --- exit statuses ----------------------------------------------------------

// --- stdout carries results only -------------------------------------------

// --- bench's files ------------------------------------------------------------

struct BenchFiles {
  testing::TempDir tmp{"bench-files"};
  testing::RunResult result;
  std::string summary, results, posteriors;
  BenchFiles(const std::string& dataset, const std::string& selection) {
    result = run(clips() + "bench --dataset " + dataset + " " + selection + " --no-progress --seed 4294967296 --out " +
                 tmp.str());
    summary = testing::read_text(tmp.path / "summary.json");
    results = testing::read_text(tmp.path / "results.csv");
    posteriors = testing::read_text(tmp.path / "posteriors.csv");
  }
};

std::vector<std::string> split(const std::string& line, char sep = ',') {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == sep) out.emplace_back();
    else out.back().push_back(c);
  }
  return out;
}

// --- ad-hoc observations -----------------------------------------------------

const std::string kE11Actions = "(left human) (wait robot) (left human) (wait robot)";
const std::string kE11Utterance = "Can you get me the yellow key?";

// --- issue 21, smaller items ----------------------------------------------------

}  // namespace cli_conventions_test
using namespace cli_conventions_test;
}  // namespace clips::eval
