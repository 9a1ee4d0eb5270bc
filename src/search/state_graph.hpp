#pragma once
// StateGraph: the states that the policies of one task have generated, each
// with a small integer id, and for every state some policy has expanded, its
// successors (action, child id) in the task's action order.
//
// The hypotheses of a belief search the same neighbourhood with different
// goals and costs; sharing one graph generates each state's successors once
// rather than once per hypothesis. Policies keep their own values, indexed by
// these ids.
//
// Thread-safe for policies refined in parallel: state words and successor
// lists never move once written (chunked storage), a state's successors are
// published with release/acquire, so reading them takes no lock; only lookups
// by state and first expansions lock.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "pddl/task.hpp"
#include "util/spin_mutex.hpp"

namespace clips::search {

class StateGraph {
 public:
  struct Successor {
    pddl::ActionId action;
    int child;  // state id
  };

  explicit StateGraph(std::shared_ptr<const pddl::Task> task);
  ~StateGraph();
  StateGraph(const StateGraph&) = delete;
  StateGraph& operator=(const StateGraph&) = delete;

  const pddl::Task& task() const { return *task_; }
  int words() const { return words_; }
  // Ids are 0 .. size() - 1, in insertion order.
  int size() const { return size_.load(std::memory_order_acquire); }

  // The id of state `s`, or -1 if it was never inserted.
  int find(const uint64_t* s) const;
  // The id of state `s`, inserting it if new.
  int insert(const uint64_t* s);
  // The words of state `id` (valid for the graph's lifetime).
  const uint64_t* state(int id) const {
    return state_chunks_[static_cast<size_t>(id) >> kChunkBits].load(std::memory_order_acquire) +
           (static_cast<size_t>(id) & (kChunk - 1)) * static_cast<size_t>(words_);
  }
  // A hint that successors(id) will be asked for soon (a cache prefetch).
  void prefetch(int id) const { __builtin_prefetch(&info(id)); }
  // Every applicable action of state `id` with its successor, generated on
  // the first call for that state.
  std::span<const Successor> successors(int id) {
    const uint64_t v = info(id).load(std::memory_order_acquire);
    return view(v != 0 ? v : expand(id));
  }

 private:
  static constexpr int kChunkBits = 14;
  static constexpr size_t kChunk = size_t{1} << kChunkBits;      // states per chunk
  static constexpr size_t kMaxChunks = size_t{1} << 13;           // 2^27 states at most
  static constexpr size_t kSuccChunk = size_t{1} << 16;           // successors per chunk

  std::atomic<uint64_t>& info(int id) const {
    return info_chunks_[static_cast<size_t>(id) >> kChunkBits].load(std::memory_order_acquire)
        [static_cast<size_t>(id) & (kChunk - 1)];
  }
  // info value: ((first successor index + 1) << 32) | count; 0 = not expanded.
  // A state's successors are contiguous: more than a chunk's worth get an
  // array of their own spanning several chunk indices.
  std::span<const Successor> view(uint64_t v) const {
    const size_t first = (v >> 32) - 1;
    const Successor* chunk = succ_chunks_[first / kSuccChunk].load(std::memory_order_acquire);
    return {chunk + first % kSuccChunk, static_cast<size_t>(v & 0xffffffffu)};
  }
  uint64_t expand(int id);
  int find_locked(const uint64_t* s, uint64_t h) const;
  int insert_locked(const uint64_t* s);
  int insert_locked(const uint64_t* s, uint64_t hash);
  void grow_table();

  std::shared_ptr<const pddl::Task> task_;
  int words_;
  std::atomic<int> size_{0};
  // Fixed directories of chunk pointers, so readers never see them move.
  std::unique_ptr<std::atomic<uint64_t*>[]> state_chunks_;
  std::unique_ptr<std::atomic<std::atomic<uint64_t>*>[]> info_chunks_;
  std::unique_ptr<std::atomic<Successor*>[]> succ_chunks_;  // pointers into succ_arrays_
  std::vector<std::unique_ptr<Successor[]>> succ_arrays_;   // owns the successors (guarded by mutex_)
  size_t succ_size_ = 0;  // successors stored (index of the next free slot)

  mutable util::SpinMutex mutex_;       // guards everything below and all writes
  std::vector<uint64_t> table_;         // open addressing: 0 = empty, else tag | (id + 1)
  std::vector<uint64_t> hashes_;        // per id
};

}  // namespace clips::search
