#pragma once
// The includes, helpers and fixtures of the domains tests in dkg_scale_test.cpp, shared by
// the files of that name in tests/domains/ and its label folders
// (docs/testing.md, "Labels").
// Maps beyond 64 objects: the 128-bit object masks of the mDKG heuristics
// (dkg_mask.hpp) and a generated 40x40 map with 64 gems, on which the map
// analysis builds, both heuristics evaluate and A* finds a plan to a gem whose
// object index is 64 or more.
#include <gtest/gtest.h>

#include <vector>

#include "domains/builtin/packs.hpp"
#include "domains/dkg/dkg_generate.hpp"
#include "domains/dkg/dkg_heuristic.hpp"
#include "domains/dkg/dkg_mask.hpp"
#include "domains/pack.hpp"
#include "model/spec.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"
#include "util/rng.hpp"
#include "dkg_profiles.hpp"

namespace clips::domains::dkg {
namespace dkg_scale_test {

struct BigMap {
  std::shared_ptr<const pddl::Task> task;
  BigMap() {
    GenerateParams p;
    p.width = p.height = 40;
    p.counts = {{"gem", 64}, {"key", 2}, {"door", 2}};
    p.problem_name = "big";
    util::Rng rng(11);
    std::optional<GeneratedProblem> g;
    for (int i = 0; i < 200 && !g; ++i) g = generate_dkg_problem(p, rng);
    if (!g) throw std::runtime_error("no 40x40 map in 200 draws");
    auto d = std::make_shared<pddl::Domain>(
        pddl::load_domain(paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl"));
    auto pr = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, g->pddl, "big.pddl"));
    auto pack = builtin_pack("doors-keys-gems");
    task = std::make_shared<const pddl::Task>(d, pr, pack->spec().grounding);
  }
};

}  // namespace dkg_scale_test
using namespace dkg_scale_test;
}  // namespace clips::domains::dkg
