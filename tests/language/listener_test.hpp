#pragma once
// The includes, helpers and fixtures of the language tests in listener_test.cpp, shared by
// the files of that name in tests/language/ and its label folders
// (docs/testing.md, "Labels").
// Literal listener mechanics (spec 9.7, VH spec 7.1-7.2): candidates, command
// counts, prompts, the scored continuation, temperature and the posterior.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "language/dataset_fixture.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::language {
namespace listener_test {

using commands::Command;
using commands::Term;

// Records every batch and scores a request by the first registered substring
// of its prompt's last "Input:" line (default -10).
class FakeModel : public lm::LanguageModel {
 public:
  std::map<std::string, double> by_command;
  std::vector<std::vector<lm::ScoreRequest>> calls;
  std::string name() const override { return "fake"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    calls.push_back(batch);
    std::vector<double> out;
    for (const auto& r : batch) {
      const std::string query = r.prompt.substr(r.prompt.rfind("Input: "));
      double s = -10;
      for (const auto& [needle, v] : by_command)
        if (query.find(needle) != std::string::npos) {
          s = v;
          break;
        }
      out.push_back(s);
    }
    return out;
  }
};

std::vector<std::string> printed(const std::vector<Term>& terms) {
  std::vector<std::string> out;
  for (const auto& t : terms) out.push_back(commands::to_pddl(t));
  return out;
}

size_t count_with_actions(const std::vector<Command>& cmds, size_t n) {
  return static_cast<size_t>(std::count_if(cmds.begin(), cmds.end(), [n](const Command& c) { return c.actions.size() == n; }));
}

class DkgListener : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset at " << paths::dkg_dataset();
    data_ = std::make_unique<testing::DatasetFixture>(paths::dkg_dataset());
  }
  std::unique_ptr<testing::DatasetFixture> data_;
};

}  // namespace listener_test
using namespace listener_test;
}  // namespace clips::language
