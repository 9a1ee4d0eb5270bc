#pragma once
// The includes, helpers and fixtures of the search tests in state_registry_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
// StateRegistry / StateMap: ids in insertion order across table growth and
// clear(), lookups with precomputed hashes, and A* with a reused workspace
// giving the same result as a fresh search.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "data/dataset.hpp"
#include "heuristics/basic.hpp"
#include "search/astar.hpp"
#include "search/state_registry.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;
