#pragma once
// A grounded state: a fixed-length array of 64-bit words.
//
//   words[0 .. atom_words)            one bit per dynamic ground atom
//   words[atom_words .. total_words)  dynamic numeric fluents, four int16 per word
//
// Static facts and fluents (those no action can change) are folded into the
// task at grounding time and are not stored. A State is a small value type;
// hot loops (search, successor generation) work on raw `const uint64_t*`
// views of states held side by side in a StateRegistry (search/).
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace clips::pddl {

inline uint64_t hash_words(const uint64_t* w, size_t n) {
  // 64-bit multiply-xorshift mix per word; states are short so this is cheap.
  uint64_t h = 0x9e3779b97f4a7c15ull ^ (n * 0x100000001b3ull);
  for (size_t i = 0; i < n; ++i) {
    uint64_t k = w[i] * 0xbf58476d1ce4e5b9ull;
    k ^= k >> 31;
    h = (h ^ k) * 0x94d049bb133111ebull;
    h ^= h >> 29;
  }
  return h;
}

inline bool get_bit(const uint64_t* w, int bit) { return (w[bit >> 6] >> (bit & 63)) & 1u; }
inline void set_bit(uint64_t* w, int bit, bool v) {
  uint64_t m = uint64_t{1} << (bit & 63);
  if (v) w[bit >> 6] |= m;
  else w[bit >> 6] &= ~m;
}
inline int16_t get_num(const uint64_t* w, int base_word, int slot) {
  return static_cast<int16_t>(static_cast<uint16_t>(w[base_word + (slot >> 2)] >> ((slot & 3) * 16)));
}
inline void set_num(uint64_t* w, int base_word, int slot, int16_t v) {
  int sh = (slot & 3) * 16;
  uint64_t& x = w[base_word + (slot >> 2)];
  x = (x & ~(uint64_t{0xffff} << sh)) | (uint64_t{static_cast<uint16_t>(v)} << sh);
}

struct State {
  std::vector<uint64_t> words;

  const uint64_t* data() const { return words.data(); }
  uint64_t* data() { return words.data(); }
  bool operator==(const State& o) const { return words == o.words; }
  bool operator!=(const State& o) const { return words != o.words; }
  uint64_t hash() const { return hash_words(words.data(), words.size()); }
};

struct StateHash {
  size_t operator()(const State& s) const { return s.hash(); }
};

}  // namespace clips::pddl
