#pragma once
// The includes, helpers and fixtures of the report tests in report_test.cpp, shared by
// the files of that name in tests/report/ and its label folders
// (docs/testing.md, "Labels").
// `clips bench --report` on the repo's small example dataset: summary.json,
// results.csv, the HTML report and its pictures, and the page rendered in
// headless Chromium (skipped when /usr/bin/chromium is absent).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "eval/bench.hpp"
#include "report/report.hpp"
#include "eval/support.hpp"
#include "render/image.hpp"

namespace clips::report {
namespace testing = eval::testing;  // the CLI test helpers (eval/support.hpp)
namespace report_test {

namespace fs = std::filesystem;
using testing::clips_binary;
using testing::examples_dkg;

const std::vector<std::string> kPlans = {"e1.1.keys", "e1.2.keys", "e2.1.doors", "e2.2.keys"};

class BenchReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new testing::TempDir("bench-report");
    std::string plans;
    for (auto& p : kPlans) plans += " " + p;
    result_ = new testing::RunResult(testing::run(
        "env -u CLIPS_CHAT_BASE_URL " + clips_binary() + " bench --dataset " + examples_dkg() + " --plans" + plans +
        " --no-progress --jobs 2 --out " + tmp_->str() + " --report " + tmp_->str() + "/report"));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete tmp_;
  }
  static inline testing::TempDir* tmp_ = nullptr;
  static inline testing::RunResult* result_ = nullptr;
};

}  // namespace report_test
using namespace report_test;
}  // namespace clips::report
