#pragma once
// The includes, helpers and fixtures of the lm tests in http_client_test.cpp, shared by
// the files of that name in tests/lm/ and its label folders
// (docs/testing.md, "Labels").
// HttpClient details not covered through the two backends.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "lm/http_client.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::lm {
namespace http_client_test {

using namespace std::chrono_literals;

}  // namespace http_client_test
using namespace http_client_test;
}  // namespace clips::lm
