#pragma once
// The paper's cost profiles C1..C4 (clips-spec.md 4.2) as the bundled
// doors-keys-gems pack defines them: tests that need one read it from the
// pack, so the pack's data is the only definition.
#include <string>

#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"

namespace clips::fixtures {

inline model::CostProfile dkg_profile(int index) {
  return domains::builtin_pack("doors-keys-gems")->cost_profile("C" + std::to_string(index));
}

}  // namespace clips::fixtures
