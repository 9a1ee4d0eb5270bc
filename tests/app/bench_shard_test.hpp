#pragma once
// The includes, helpers and fixtures of the app tests in bench_shard_test.cpp, shared by
// the files of that name in tests/app/ and its label folders
// (docs/testing.md, "Labels").
// `clips bench --shard K/N` and `clips bench merge` on the repo's example
// dataset (4 plans): three merged shards give the files of one unsharded run,
// and merge refuses parts that do not belong together.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "eval/support.hpp"

namespace clips::eval {
namespace bench_shard_test {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::clips_binary;
using testing::contains;
using testing::examples_dkg;
using testing::parse_csv;
using testing::read_text;
using testing::run;

// Three methods (an inference method, the action-only baseline and a literal
// listener) keep the four plans under a second or two.
const std::string kBench = " bench --dataset " + examples_dkg() +
                           " --methods clips,action_only,literal_naive --no-progress --jobs 1";

std::string merge_command(const std::string& out, const std::vector<fs::path>& parts, const std::string& flags = "") {
  std::string cmd = clips_binary() + " bench merge --out " + out + " " + flags;
  for (const auto& p : parts) cmd += " " + p.string();
  return cmd;
}

// results.csv without its timing column.
std::vector<std::vector<std::string>> results_without_seconds(const fs::path& dir) {
  auto rows = parse_csv(read_text(dir / "results.csv"));
  if (rows.empty()) return rows;
  const auto at = std::find(rows[0].begin(), rows[0].end(), "seconds") - rows[0].begin();
  for (auto& row : rows)
    if (at < static_cast<long>(row.size())) row.erase(row.begin() + at);
  return rows;
}

// summary.json without the fields that tell one run from another in time
// (wall_seconds, max_rss_mb, date, latency) and the shards' bookkeeping.
json summary_without_timing(const fs::path& dir) {
  json j = json::parse(read_text(dir / "summary.json"));
  for (const char* k : {"wall_seconds", "max_rss_mb", "date", "shards", "latency"}) j.erase(k);
  return j;
}

// outcomes.json's plans without their timings.
json plans_without_timing(const fs::path& dir) {
  json plans = json::parse(read_text(dir / "outcomes.json"))["plans"];
  for (auto& p : plans) {
    p.erase("seconds");
    p.erase("step_seconds");
    p.erase("step_work_seconds");
    for (auto& m : p["methods"]) {
      m.erase("seconds");
      m.erase("decision_seconds");
    }
  }
  return plans;
}

// The results table in a command's output: its lines less the timing lines
// ("... s wall ...", "latency: ...", "time: ...") and the notes on stderr ("wrote ...").
std::vector<std::string> table_without_timing(const std::string& out) {
  std::vector<std::string> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);)
    if (!contains(line, " s wall") && line.rfind("wrote ", 0) != 0 && line.rfind("latency: ", 0) != 0 &&
        line.rfind("time: ", 0) != 0)
      lines.push_back(line);
  return lines;
}

std::vector<std::string> plan_column(const fs::path& dir) {
  std::vector<std::string> plans;
  const auto rows = parse_csv(read_text(dir / "results.csv"));
  for (size_t i = 1; i < rows.size(); ++i)
    if (plans.empty() || plans.back() != rows[i][0]) plans.push_back(rows[i][0]);
  return plans;
}

// One unsharded run, its three shards and their merge, shared by the tests
// and each made on first use (ctest runs every test in a process of its own,
// and most tests need the shards only).
class BenchShardTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { tmp_ = new testing::TempDir("bench-shard"); }
  static void TearDownTestSuite() {
    delete tmp_;
    tmp_ = nullptr;
    runs_.clear();
  }
  static fs::path dir(const std::string& name) { return tmp_->path / name; }
  // The output of a command, run once per suite.
  static const testing::RunResult& once(const std::string& name, const std::string& command) {
    auto it = runs_.find(name);
    if (it == runs_.end()) it = runs_.emplace(name, run(command)).first;
    return it->second;
  }
  static const testing::RunResult& whole() {
    return once("whole", clips_binary() + kBench + " --seed 7 --out " + dir("whole").string());
  }
  static const testing::RunResult& shard(int k) {
    return once("shard" + std::to_string(k), clips_binary() + kBench + " --seed 7 --shard " + std::to_string(k) +
                                                 "/3 --out " + part_dir(k).string());
  }
  static fs::path part_dir(int k) { return tmp_->path / "parts" / std::to_string(k); }
  // Shard k's folder, after running it (a failed run fails the test).
  static fs::path part(int k) {
    const auto& r = shard(k);
    EXPECT_EQ(r.status, 0) << r.out;
    return part_dir(k);
  }
  // A copy of shard k's folder that a test may change.
  static fs::path copy_of(int k, const std::string& name) {
    fs::copy(part(k), dir(name), fs::copy_options::recursive);
    return dir(name);
  }
  static inline testing::TempDir* tmp_ = nullptr;
  static inline std::map<std::string, testing::RunResult> runs_;
};

}  // namespace bench_shard_test
using namespace bench_shard_test;
}  // namespace clips::eval
