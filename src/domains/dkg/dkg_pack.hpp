#pragma once
// The compiled hooks of pack code "doors-keys-gems" (the paper's Doors, Keys &
// Gems; its data is data/domains/doors-keys-gems/pack.json): the grid
// heuristics, map checks, literal candidates, state text, STRIPS export and
// map generator. domains/builtin/packs.cpp registers them.
#include <string>

#include "domains/pack.hpp"

namespace clips::domains::dkg {

// The pack of a spec whose code is "doors-keys-gems".
PackPtr make_dkg_pack(PackSpec spec);
// What a domain lacks of what these hooks read (types, predicates,
// functions), e.g. "no function (walls)"; "" when it has all of it.
std::string dkg_misfit(const pddl::Domain& domain);

}  // namespace clips::domains::dkg
