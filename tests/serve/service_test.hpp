#pragma once
// The includes, helpers and fixtures of the serve tests in service_test.cpp, shared by
// the files of that name in tests/serve/ and its label folders
// (docs/testing.md, "Labels").
// The request handlers of `clips serve`, called in process (no socket): every
// documented error, the limits, and a short game.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "data/dataset.hpp"
#include "language/listener.hpp"
#include "app/choice_option.hpp"
#include "engine/methods.hpp"
#include "engine/policies.hpp"
#include "serve/api_schema.hpp"
#include "serve/frontends.hpp"
#include "serve/service.hpp"

#include <sstream>

namespace clips::serve {
namespace service_test {

using nlohmann::json;

const std::string kExamples = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";

std::shared_ptr<lm::LanguageModel> shared_lm() {
  static auto lm = language::make_language_model("embedded");
  return lm;
}

// A clock the tests move by hand (idle expiry).
struct FakeClock {
  std::atomic<int64_t> seconds{1000};
  Service::Clock::time_point now() const {
    return Service::Clock::time_point(std::chrono::duration_cast<Service::Clock::duration>(std::chrono::seconds(seconds.load())));
  }
};

struct Fixture : ::testing::Test {
  FakeClock clock;
  std::unique_ptr<Service> make(ServiceLimits limits = {}) {
    return std::make_unique<Service>(std::vector<std::string>{kExamples}, limits, shared_lm(),
                                     [this] { return clock.now(); });
  }
  static json body(const Reply& r) { return json::parse(r.body); }
  static std::string create(Service& s, const std::string& problem = "e1", const std::string& plan = "e1.1.keys") {
    Reply r = s.handle("POST", "/api/sessions", json{{"dataset", "doors-keys-gems"}, {"problem", problem}, {"plan", plan}}.dump());
    EXPECT_EQ(r.status, 201) << r.body;
    return body(r).value("id", "");
  }
};

nlohmann::ordered_json read_api_schema() {
  std::ifstream in(std::string(CLIPS_SOURCE_DIR) + "/data/schema/serve-api.openapi.json");
  return nlohmann::ordered_json::parse(in);
}

bool lists(const nlohmann::ordered_json& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace service_test
using namespace service_test;
}  // namespace clips::serve
