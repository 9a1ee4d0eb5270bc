#pragma once
// The includes, helpers and fixtures of the app tests in cli_input_test.cpp, shared by
// the files of that name in tests/app/ and its label folders
// (docs/testing.md, "Labels").
// The `clips` command line on bad input: options and values that are refused
// at parse time or before any work, with messages that name the problem.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "eval/support.hpp"
#include "test_paths.hpp"

namespace clips::eval {
namespace cli_input_test {

using testing::clips_binary;
using testing::examples_dkg;
using testing::run;

using testing::contains;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// --- numeric options (item 6) ---------------------------------------------

struct BadValue {
  std::string args;    // after `clips`
  std::string option;  // named in the message
};

// --- show --step (item 5) --------------------------------------------------

// --- plan (items 1 and 7) --------------------------------------------------

// --- unknown subcommand (item 8) -------------------------------------------

// --- listen (item 9) -------------------------------------------------------

}  // namespace cli_input_test
using namespace cli_input_test;
}  // namespace clips::eval
