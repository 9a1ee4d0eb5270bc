#pragma once
// The includes, helpers and fixtures of the api tests in session_test.cpp, shared by
// the files of that name in tests/api/ and its label folders
// (docs/testing.md, "Labels").
// The public session API (include/clips/session.hpp): same posteriors as
// `clips infer`, errors that leave a session unchanged, assistance, threads.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include <nlohmann/json.hpp>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "run_command.hpp"
#include "test_paths.hpp"

namespace session_test {

std::string examples_dkg() { return clips::paths::examples_dir() + "/doors-keys-gems"; }

using clips::tests::stdout_of;

void expect_near_all(const std::vector<double>& a, const std::vector<double>& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << where << " goal " << i;
}

// Replays a dataset plan through a Session, an action and an utterance at a
// time, and compares every step with `clips infer --json` (utterances are
// heard in the state they were said in, the CLI's default timing).
void check_replay_matches_cli(const std::string& dataset, const std::string& plan_id) {
  const auto j = nlohmann::json::parse(stdout_of(std::string(CLIPS_BINARY_DIR) + "/clips infer --json --dataset " +
                                                 dataset + " --plan " + plan_id));
  const auto ds = clips::data::Dataset::load(dataset);
  const auto& plan = ds.plan(plan_id);
  const int T = static_cast<int>(plan.observed.actions.size());
  ASSERT_EQ(static_cast<int>(j["steps"].size()), T + 1);
  auto session = clips::Session::open_dataset(dataset, plan_id);
  EXPECT_EQ(session.posterior().goals, j["goals"].get<std::vector<std::string>>());
  for (int t = 0; t <= T; ++t) {
    if (t > 0) session.observe(plan.observed.actions[t - 1].text);
    auto hear_all = [&] {
      for (const auto& u : plan.observed.utterances)
        if (u.index == t) session.hear(u.text);
    };
    // The CLI's step t holds the utterances said after t actions only at the
    // start and the end; in between they are scored in step t + 1.
    if (t == 0 || t == T) hear_all();
    std::vector<double> expected;  // the engine's posterior JSON: goals [{goal, p}]
    for (const auto& g : j["steps"][t]["posterior"]["goals"]) expected.push_back(g["p"].get<double>());
    expect_near_all(session.posterior().goal_probabilities, expected, plan_id + " t=" + std::to_string(t));
    expect_near_all(session.trace().at(t).posterior.goal_probabilities, expected, plan_id + " trace t=" + std::to_string(t));
    if (t != 0 && t != T) hear_all();
  }
  EXPECT_EQ(session.t(), T);
}

}  // namespace session_test
using namespace session_test;
