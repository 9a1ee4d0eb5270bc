#include "search/state_graph.hpp"

#include <stdexcept>
#include <string>

#include "pddl/state.hpp"

namespace clips::search {

namespace {
constexpr uint64_t kTagMask = ~uint64_t{0xffffffff};  // upper hash half; lower half = id + 1
int slot_id(uint64_t e) { return static_cast<int>(static_cast<uint32_t>(e)) - 1; }
}  // namespace

StateGraph::StateGraph(std::shared_ptr<const pddl::Task> task)
    : task_(std::move(task)),
      words_(task_->num_words()),
      state_chunks_(new std::atomic<uint64_t*>[kMaxChunks]),
      info_chunks_(new std::atomic<std::atomic<uint64_t>*>[kMaxChunks]),
      succ_chunks_(new std::atomic<Successor*>[kMaxChunks]) {
  for (size_t c = 0; c < kMaxChunks; ++c) {
    state_chunks_[c].store(nullptr, std::memory_order_relaxed);
    info_chunks_[c].store(nullptr, std::memory_order_relaxed);
    succ_chunks_[c].store(nullptr, std::memory_order_relaxed);
  }
  table_.assign(1024, 0);
}

StateGraph::~StateGraph() {
  for (size_t c = 0; c < kMaxChunks; ++c) {
    delete[] state_chunks_[c].load(std::memory_order_relaxed);
    delete[] info_chunks_[c].load(std::memory_order_relaxed);
  }
}

int StateGraph::find_locked(const uint64_t* s, uint64_t h) const {
  const size_t mask = table_.size() - 1;
  const uint64_t tag = h & kTagMask;
  for (size_t i = h & mask;; i = (i + 1) & mask) {
    const uint64_t e = table_[i];
    if (e == 0) return -1;
    if ((e & kTagMask) != tag) continue;
    const uint64_t* t = state(slot_id(e));
    bool same = true;
    for (int w = 0; w < words_ && same; ++w) same = t[w] == s[w];
    if (same) return slot_id(e);
  }
}

int StateGraph::find(const uint64_t* s) const {
  const uint64_t h = pddl::hash_words(s, static_cast<size_t>(words_));
  std::lock_guard lock(mutex_);
  return find_locked(s, h);
}

int StateGraph::insert(const uint64_t* s) {
  std::lock_guard lock(mutex_);
  return insert_locked(s);
}

int StateGraph::insert_locked(const uint64_t* s) {
  return insert_locked(s, pddl::hash_words(s, static_cast<size_t>(words_)));
}

int StateGraph::insert_locked(const uint64_t* s, uint64_t h) {
  if (const int id = find_locked(s, h); id >= 0) return id;
  const int id = size_.load(std::memory_order_relaxed);
  const size_t chunk = static_cast<size_t>(id) >> kChunkBits;
  if (chunk >= kMaxChunks) throw std::length_error("state graph: more than 2^27 states");
  if (state_chunks_[chunk].load(std::memory_order_relaxed) == nullptr) {
    state_chunks_[chunk].store(new uint64_t[kChunk * static_cast<size_t>(words_)], std::memory_order_release);
    auto* info = new std::atomic<uint64_t>[kChunk];
    for (size_t i = 0; i < kChunk; ++i) info[i].store(0, std::memory_order_relaxed);
    info_chunks_[chunk].store(info, std::memory_order_release);
  }
  uint64_t* dst = state_chunks_[chunk].load(std::memory_order_relaxed) +
                  (static_cast<size_t>(id) & (kChunk - 1)) * static_cast<size_t>(words_);
  for (int w = 0; w < words_; ++w) dst[w] = s[w];
  hashes_.push_back(h);
  const size_t mask = table_.size() - 1;
  size_t i = h & mask;
  while (table_[i] != 0) i = (i + 1) & mask;
  table_[i] = (h & kTagMask) | static_cast<uint64_t>(id + 1);
  size_.store(id + 1, std::memory_order_release);
  if (static_cast<size_t>(id + 1) * 2 > table_.size()) grow_table();
  return id;
}

void StateGraph::grow_table() {
  std::vector<uint64_t> bigger(table_.size() * 2, 0);
  const size_t mask = bigger.size() - 1;
  for (size_t id = 0; id < hashes_.size(); ++id) {
    size_t i = hashes_[id] & mask;
    while (bigger[i] != 0) i = (i + 1) & mask;
    bigger[i] = (hashes_[id] & kTagMask) | static_cast<uint64_t>(id + 1);
  }
  table_.swap(bigger);
}

uint64_t StateGraph::expand(int id) {
  std::atomic<uint64_t>& slot = info(id);
  // The successors are generated before taking the lock (a state's words
  // never change once inserted), so two threads expanding new states only
  // wait for each other's table insertions. Both may generate the same
  // state; the first to lock publishes it.
  thread_local std::vector<pddl::ActionId> acts;
  thread_local std::vector<uint64_t> children, hashes;
  const size_t w = static_cast<size_t>(words_);
  task_->applicable_actions(state(id), acts);
  const size_t n = acts.size();
  children.resize(n * w);
  hashes.resize(n);
  for (size_t k = 0; k < n; ++k) {
    task_->apply(acts[k], state(id), children.data() + k * w);
    hashes[k] = pddl::hash_words(children.data() + k * w, w);
  }

  std::lock_guard lock(mutex_);
  if (const uint64_t v = slot.load(std::memory_order_relaxed); v != 0) return v;  // another thread did it
  // A state's successors are contiguous: start a new chunk if they do not
  // fit, and give more than a chunk's worth one array over several chunks.
  size_t first = succ_size_;
  if (first % kSuccChunk + n > kSuccChunk) first = (first / kSuccChunk + 1) * kSuccChunk;
  const size_t chunk = first / kSuccChunk;
  const size_t spans = n > kSuccChunk ? (n + kSuccChunk - 1) / kSuccChunk : 1;
  if (chunk + spans > kMaxChunks)
    throw std::length_error("state graph: more than " + std::to_string(kMaxChunks * kSuccChunk) +
                            " successors stored (the search's states have too many applicable actions)");
  if (succ_chunks_[chunk].load(std::memory_order_relaxed) == nullptr) {
    succ_arrays_.emplace_back(new Successor[spans * kSuccChunk]);
    for (size_t j = 0; j < spans; ++j)
      succ_chunks_[chunk + j].store(succ_arrays_.back().get() + j * kSuccChunk, std::memory_order_release);
  }
  Successor* out = succ_chunks_[chunk].load(std::memory_order_relaxed) + first % kSuccChunk;
  // The table slots are fetched together (cache misses into a large table).
  for (size_t k = 0; k < n; ++k) __builtin_prefetch(&table_[hashes[k] & (table_.size() - 1)]);
  for (size_t k = 0; k < n; ++k) out[k] = Successor{acts[k], insert_locked(children.data() + k * w, hashes[k])};
  succ_size_ = first + n;
  const uint64_t v = ((static_cast<uint64_t>(first) + 1) << 32) | static_cast<uint64_t>(n);
  slot.store(v, std::memory_order_release);
  return v;
}

}  // namespace clips::search
