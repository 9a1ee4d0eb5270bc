#pragma once
// The compiled hooks of pack code "virtual-home" (the paper's VirtualHome; its
// data is data/domains/virtual-home/pack.json): the value heuristics, literal
// candidates and state text. domains/builtin/packs.cpp registers them.
#include <string>

#include "domains/pack.hpp"

namespace clips::domains::vh {

// The pack of a spec whose code is "virtual-home".
PackPtr make_vh_pack(PackSpec spec);
// What a domain lacks of what these hooks read, e.g. "no type 'itype'"; ""
// when it has all of it.
std::string vh_misfit(const pddl::Domain& domain);

}  // namespace clips::domains::vh
