#pragma once
// The includes, helpers and fixtures of the multimodal tests in multimodal_test.cpp, shared by
// the files of that name in tests/multimodal/ and its label folders
// (docs/testing.md, "Labels").
// The multimodal-LLM baseline against the loopback fake chat server.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "eval/experiment.hpp"
#include "multimodal/multimodal.hpp"
#include "eval/support.hpp"
#include "language/listener.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::multimodal {
namespace testing = eval::testing;  // the CLI test helpers (eval/support.hpp)
namespace multimodal_test {

using eval::ExperimentOptions;
using eval::MethodResult;
using eval::PlanOutcome;
using eval::evaluate_plan;
using lm::fake::FakeFaults;
using lm::fake::FakeOpenAiServer;
using lm::fake::FakeReply;
using nlohmann::json;

const std::vector<std::string> kGoals = {"gem1", "gem2", "gem3", "gem4"};

// ---- parsing -------------------------------------------------------------------

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_multimodal_answer(text, kGoals);
    ADD_FAILURE() << "no error for " << text;
  } catch (const MultimodalError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// ---- end to end against the fake server ---------------------------------------

class MultimodalServer : public ::testing::Test {
 protected:
  void SetUp() override {
    server_.start();
    ds_ = std::make_unique<data::Dataset>(data::Dataset::load(testing::examples_dkg()));
    lm_ = language::make_language_model("embedded", {});
  }
  void answer(const json& j) {
    std::string text = j.dump();
    server_.set_chat_rule([text](const json&) { return text; });
  }
  ExperimentOptions options(int max_retries = 2) {
    ExperimentOptions eo;
    eo.methods = {"clips", "multimodal"};
    eo.multimodal.base_url = server_.base_url();
    eo.multimodal.model = "fake-vision";
    eo.multimodal.api_key = "";
    eo.multimodal.http.max_retries = max_retries;
    eo.multimodal.http.backoff_initial = std::chrono::milliseconds(5);
    eo.multimodal.http.total_timeout = std::chrono::milliseconds(2000);
    return eo;
  }
  const MethodResult& run(const std::string& plan, const ExperimentOptions& eo) {
    outcome_ = evaluate_plan(*ds_, ds_->plan(plan), *lm_, eo);
    EXPECT_TRUE(outcome_.error.empty()) << outcome_.error;
    const MethodResult* r = outcome_.find("multimodal");
    EXPECT_NE(r, nullptr);
    return *r;
  }
  FakeOpenAiServer server_;
  std::unique_ptr<data::Dataset> ds_;
  std::shared_ptr<lm::LanguageModel> lm_;
  PlanOutcome outcome_;
};

const json kGoodAnswer = {{"goal_probabilities", {{"gem1", 0.1}, {"gem2", 0.05}, {"gem3", 0.8}, {"gem4", 0.05}}},
                          {"actions", {"(down robot)", "(pickup robot key3)", "(handover robot human key3)"}}};

}  // namespace multimodal_test
using namespace multimodal_test;
}  // namespace clips::multimodal
