#pragma once
// The A* frontier shared by astar() and the RTAA* lookahead: a 4-ary min-heap
// on (f, h, counter) in a reusable vector (shallower than a binary heap, so
// fewer cache misses per pop). Live entries have distinct keys (counters are
// unique per node), so the expansion order is that of any exact priority
// queue: ties break toward smaller h (deeper nodes), then earlier insertion.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace clips::search {

struct OpenEntry {
  double f, h;
  uint64_t counter;
  int node;
  uint32_t version;  // stale when the node's version has moved on
};

inline bool open_before(const OpenEntry& a, const OpenEntry& b) {
  if (a.f < b.f) return true;
  if (b.f < a.f) return false;
  if (a.h < b.h) return true;
  if (b.h < a.h) return false;
  return a.counter < b.counter;
}

inline void open_push(std::vector<OpenEntry>& v, const OpenEntry& e) {
  size_t i = v.size();
  v.push_back(e);
  while (i > 0) {
    size_t p = (i - 1) / 4;
    if (!open_before(e, v[p])) break;
    v[i] = v[p];
    i = p;
  }
  v[i] = e;
}

inline void open_pop(std::vector<OpenEntry>& v) {
  const OpenEntry last = v.back();
  v.pop_back();
  const size_t n = v.size();
  if (n == 0) return;
  size_t i = 0;
  while (true) {
    size_t c = 4 * i + 1;
    if (c >= n) break;
    size_t m = c;
    for (size_t k = c + 1, e = std::min(c + 4, n); k < e; ++k)
      if (open_before(v[k], v[m])) m = k;
    if (!open_before(v[m], last)) break;
    v[i] = v[m];
    i = m;
  }
  v[i] = last;
}

}  // namespace clips::search
