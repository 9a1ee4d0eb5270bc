#pragma once
// Sets of Doors-Keys-Gems objects (agents, items, doors in DkgMapAnalysis
// order) as bit masks. 128 bits, so a map may hold up to 128 objects (the
// generator's 64 gems plus keys, doors and agents). GCC and Clang's
// `unsigned __int128` is two machine words; the helpers below keep the
// word split in one place.
#include <cstdint>

namespace clips::domains::dkg {

using ObjMask = unsigned __int128;
inline constexpr int kObjMaskBits = 128;

constexpr ObjMask mask_bit(int i) { return ObjMask{1} << i; }
constexpr bool mask_has(ObjMask m, int i) { return ((m >> i) & 1u) != 0; }
// Index of the lowest set bit; m must not be 0.
inline int mask_ctz(ObjMask m) {
  const auto lo = static_cast<uint64_t>(m);
  return lo ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(static_cast<uint64_t>(m >> 64));
}
inline int mask_popcount(ObjMask m) {
  return __builtin_popcountll(static_cast<uint64_t>(m)) + __builtin_popcountll(static_cast<uint64_t>(m >> 64));
}
// Calls f(i) for every set bit, lowest first.
template <class F>
inline void mask_for_each(ObjMask m, F&& f) {
  for (; m; m &= m - 1) f(mask_ctz(m));
}

}  // namespace clips::domains::dkg
