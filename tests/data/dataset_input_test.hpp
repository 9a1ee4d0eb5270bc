#pragma once
// The includes, helpers and fixtures of the data tests in dataset_input_test.cpp, shared by
// the files of that name in tests/data/ and its label folders
// (docs/testing.md, "Labels").
// Bad inputs the dataset loader must reject with an error naming the file
// (and line, entry or object), instead of loading them and giving a wrong
// answer later. Each test corrupts a copy of the repo's example
// Doors-Keys-Gems dataset, or of a slice of the shared VirtualHome dataset
// (skipped when ../shared/dataset is absent).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "data/validate.hpp"
#include "test_paths.hpp"

namespace clips::data {
namespace dataset_input_test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Replaces the one occurrence of `from` in file `p`.
void replace(const fs::path& p, const std::string& from, const std::string& to) {
  std::string s = read(p);
  size_t at = s.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << p;
  ASSERT_EQ(s.find(from, at + 1), std::string::npos) << from << " twice in " << p;
  write(p, s.replace(at, from.size(), to));
}

// A fresh directory per test, removed after it.
fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return fs::temp_directory_path() /
         ("clips-data-test-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" + info->name());
}

fs::path scratch() {
  fs::path dir = scratch_dir();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

class DatasetInput : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove_all(scratch_dir()); }
};

// The example mDKG dataset: problems e1, e2; plans e1.1.keys, e1.2.keys,
// e2.1.doors, e2.2.keys, each with one utterance and utterance files.
fs::path dkg_copy() {
  fs::path dir = scratch() / "dkg";
  fs::copy(paths::examples_dir() + "/doors-keys-gems", dir, fs::copy_options::recursive);
  return dir;
}

// Problem 1 of the shared VirtualHome dataset with two of its plans
// (1.2.salad_veggie has two utterances).
fs::path vh_slice() {
  fs::path src = paths::vh_dataset(), dir = scratch() / "vh";
  fs::create_directories(dir / "problems");
  fs::copy(src / "domain.pddl", dir / "domain.pddl");
  fs::copy(src / "goals", dir / "goals", fs::copy_options::recursive);
  fs::copy(src / "problems" / "1.pddl", dir / "problems" / "1.pddl");
  for (const char* kind : {"observed", "completed"}) {
    fs::create_directories(dir / "plans" / kind);
    for (const char* id : {"1.1.stew_chicken", "1.2.salad_veggie"})
      fs::copy(src / "plans" / kind / (std::string(id) + ".pddl"), dir / "plans" / kind / (std::string(id) + ".pddl"));
  }
  return dir;
}

// The error of loading `dir`: the load's own, else those kept for the plans
// that failed to load and for stimuli.json (they are raised only on use).
std::string load_error(const fs::path& dir) {
  try {
    auto ds = Dataset::load(dir.string());
    std::string kept;
    for (const auto& b : ds.broken_plans()) kept += b.error + "\n";
    kept += ds.stimuli_error();
    if (!kept.empty()) return kept;
  } catch (const InputError& e) {
    return e.what();
  }
  return "<loaded without error>";
}

std::string task_error(const fs::path& dir, const std::string& problem) {
  try {
    Dataset::load(dir.string()).task(problem);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<grounded without error>";
}

// ---- 1: objects must start on the grid (or, for items, in an agent's hands)

// ---- 2: a VirtualHome goal set lists each goal once

// Goal labels are file names written into every JSON output (issue 46): a
// label that is not UTF-8 made `infer --json` fail with an internal error
// (nlohmann type_error 316, exit 8); one with a path walked out of
// goals/definitions/. Both are refused at load, naming the set's file and line.
fs::path kitchen_copy() {
  fs::path dir = scratch() / "kitchen";
  fs::copy(paths::source_dir() + "/data/datasets/kitchen", dir, fs::copy_options::recursive);
  return dir;
}

// ---- 3: an utterance file holds exactly one utterance

// ---- 4: observed plans: one utterance in mDKG, no empty utterances, no empty plans

// ---- 5: stimuli.json

std::string stimulus(const std::string& goal = "[1]", const std::string& timesteps = "4",
                     const std::string& utterance = "\"Can you get me the yellow key?\"",
                     const std::string& best = "[[3]]", const std::string& name = "\"e1.1.keys\"",
                     const std::string& type = "\"keys\"") {
  return "{\"name\": " + name + ", \"type\": " + type + ", \"utterance\": " + utterance +
         ", \"timesteps\": " + timesteps + ", \"option_count\": 3, \"goal\": " + goal +
         ", \"best_option\": " + best + "}";
}

// ---- 6: utterances must be UTF-8, checked when loading

// ---- the paper's datasets keep loading and validating

// ---- one bad plan file does not block the others

}  // namespace dataset_input_test
using namespace dataset_input_test;
}  // namespace clips::data
