#pragma once
// A seeded random source whose draws are the same on every platform: the
// engine is std::mt19937_64 (its output is fixed by the standard), and the
// integer, real and weighted draws below are made from that output here
// rather than by the <random> distributions, whose algorithms differ between
// standard libraries. What `clips generate` writes depends only on its
// arguments and seed.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace clips::util {

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  // A seed for an independent stream: `seed` mixed with the labels (e.g. a
  // problem or plan number), so that one problem's draws do not depend on how
  // many draws an earlier one made.
  static uint64_t derive(uint64_t seed, std::initializer_list<uint64_t> labels) {
    uint64_t x = splitmix(seed);
    for (uint64_t l : labels) x = splitmix(x ^ splitmix(l + 0x9e3779b97f4a7c15ull));
    return x;
  }

  uint64_t next() { return engine_(); }

  // Uniform in [lo, hi] (lo <= hi), without modulo bias.
  int64_t uniform_int(int64_t lo, int64_t hi) {
    if (hi < lo) throw std::invalid_argument("Rng::uniform_int: empty range");
    const uint64_t span = static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo);
    if (span == UINT64_MAX) return static_cast<int64_t>(next());
    const uint64_t n = span + 1;
    const uint64_t limit = UINT64_MAX - UINT64_MAX % n;  // reject the incomplete last block
    uint64_t x;
    do x = next();
    while (x >= limit);
    return lo + static_cast<int64_t>(x % n);
  }
  // An index in [0, n), n > 0.
  size_t index(size_t n) { return static_cast<size_t>(uniform_int(0, static_cast<int64_t>(n) - 1)); }

  // Uniform in [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // An index drawn with probability proportional to the (non-negative,
  // finite) weights; throws if they sum to zero.
  size_t weighted(std::span<const double> weights) {
    double total = 0;
    for (double w : weights) total += (w > 0 && std::isfinite(w)) ? w : 0.0;
    if (!(total > 0)) throw std::invalid_argument("Rng::weighted: no positive weight");
    const double r = uniform01() * total;
    double acc = 0;
    size_t last = 0;
    for (size_t i = 0; i < weights.size(); ++i) {
      if (!(weights[i] > 0 && std::isfinite(weights[i]))) continue;
      acc += weights[i];
      last = i;
      if (r < acc) return i;
    }
    return last;  // rounding at the top end
  }

  // Fisher-Yates with this generator's index draws.
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[index(i)]);
  }

 private:
  static uint64_t splitmix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }

  std::mt19937_64 engine_;
};

}  // namespace clips::util
