#pragma once
// The includes, helpers and fixtures of the scenes tests in scenes_test.cpp, shared by
// the files of that name in tests/scenes/ and its label folders
// (docs/testing.md, "Labels").
// State -> scene conversion and `clips render` output.
#include <gif_lib.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scenes/scenes.hpp"
#include "domains/dkg/dkg_world.hpp"
#include "domains/vh/vh_world.hpp"
#include "eval/support.hpp"
#include "render/image.hpp"

namespace clips::scenes {
namespace testing = eval::testing;  // the CLI test helpers (eval/support.hpp)
namespace scenes_test {

using testing::clips_binary;
using testing::examples_dkg;

const render::GridObject& object(const render::GridScene& s, const std::string& name) {
  const render::GridObject* o = s.find(name);
  EXPECT_NE(o, nullptr) << name;
  static render::GridObject none;
  return o ? *o : none;
}

}  // namespace scenes_test
using namespace scenes_test;
}  // namespace clips::scenes
