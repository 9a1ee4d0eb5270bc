#pragma once
// FNV-1a: a small, stable byte hash (unlike std::hash, the same on every run
// and build), for cache keys, checksums and colour choices.
#include <cstdint>
#include <string_view>

namespace clips::util {

inline constexpr std::uint64_t kFnv64Offset = 1469598103934665603ull;

inline std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t h = kFnv64Offset) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

inline std::uint32_t fnv1a32(std::string_view bytes) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : bytes) h = (h ^ c) * 16777619u;
  return h;
}

}  // namespace clips::util
