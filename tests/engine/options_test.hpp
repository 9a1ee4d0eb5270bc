#pragma once
// The includes, helpers and fixtures of the engine tests in options_test.cpp, shared by
// the files of that name in tests/engine/ and its label folders
// (docs/testing.md, "Labels").
// The one particle option table (engine/options.hpp): the CLI's flags,
// Python's keywords and the server's JSON read the same names and give the
// same message for the same bad value.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "clips/clips.hpp"
#include "engine/options.hpp"
#include "language/listener.hpp"
#include "serve/service.hpp"
#include "run_command.hpp"
#include "test_paths.hpp"

namespace options_test {

using nlohmann::json;

const std::string kDataset = clips::paths::examples_dir() + "/doors-keys-gems";

using clips::tests::output_of;

// One bad value as each front end spells it, and the message all must give.
struct BadValue {
  std::string name;
  std::string cli;     // the flag's text
  std::string python;  // a Python literal
  json json_value;
  std::string message;
};

const std::vector<BadValue> kBad = {
    {"ess_threshold", "1.5", "1.5", 1.5, "ess_threshold must be a number from 0 to 1, got 1.5"},
    {"particles", "2000000", "2000000", 2000000, "particles must be an integer from 0 to 1000000, got 2000000"},
    {"rejuvenation_moves", "101", "101", 101, "rejuvenation_moves must be an integer from 0 to 100, got 101"},
    {"proposal_groups", "0", "0", 0, "proposal_groups must be an integer from 1 to 64, got 0"},
    {"rejuvenate", "sometimes", "'sometimes'", "sometimes",
     "rejuvenate must be one of evidence, utterances, resampling, got 'sometimes'"},
    {"particle_filters", "some", "'some'", "some", "particle_filters must be one of all, clips, got 'some'"},
    {"particle_estimate", "counts", "'counts'", "counts",
     "particle_estimate must be one of support, weights, got 'counts'"},
};

}  // namespace options_test
using namespace options_test;
