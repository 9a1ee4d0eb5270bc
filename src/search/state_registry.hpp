#pragma once
// StateRegistry: states packed side by side in one array, each identified by
// a small integer id (Fast Downward's idea). Search nodes, value tables and
// reusable trees hold ids, never copies of state words.
// StateMap<T>: a registry plus one T per id.
//
// The open-addressing table stores, per slot, the id and the upper half of
// the state's hash, so a probe touches the state words only on a likely
// match. Ids are handed out in insertion order and never depend on the table,
// so callers iterating ids see the same order whatever the table layout.
// Callers probing several maps with one state may hash once (hash()) and pass
// the hash to the *_hashed variants.
#include <cstdint>
#include <vector>

#include "pddl/state.hpp"

namespace clips::search {

class StateRegistry {
 public:
  explicit StateRegistry(int words = 0) : words_(words) { table_.assign(kMinSlots, 0); }

  int words() const { return words_; }
  int size() const { return static_cast<int>(hashes_.size()); }
  const uint64_t* get(int id) const { return data_.data() + static_cast<size_t>(id) * words_; }
  pddl::State state(int id) const { return pddl::State{std::vector<uint64_t>(get(id), get(id) + words_)}; }
  uint64_t hash(const uint64_t* s) const { return pddl::hash_words(s, words_); }

  int find(const uint64_t* s) const { return find_hashed(s, hash(s)); }
  int find_hashed(const uint64_t* s, uint64_t h) const {
    const size_t mask = table_.size() - 1;
    const uint64_t tag = h & kTagMask;
    for (size_t i = h & mask;; i = (i + 1) & mask) {
      const uint64_t e = table_[i];
      if (e == 0) return -1;
      if ((e & kTagMask) == tag && same(get(slot_id(e)), s)) return slot_id(e);
    }
  }

  // Returns the id of `s`, adding it if new (then *added is set).
  int insert(const uint64_t* s, bool* added = nullptr) { return insert_hashed(s, hash(s), added); }
  int insert_hashed(const uint64_t* s, uint64_t h, bool* added = nullptr) {
    const size_t mask = table_.size() - 1;
    const uint64_t tag = h & kTagMask;
    size_t i = h & mask;
    for (;; i = (i + 1) & mask) {
      const uint64_t e = table_[i];
      if (e == 0) break;
      if ((e & kTagMask) == tag && same(get(slot_id(e)), s)) {
        if (added) *added = false;
        return slot_id(e);
      }
    }
    const int id = size();
    data_.insert(data_.end(), s, s + words_);
    hashes_.push_back(h);
    table_[i] = tag | static_cast<uint64_t>(id + 1);
    if (added) *added = true;
    if (static_cast<size_t>(size()) * 2 > table_.size()) grow();
    return id;
  }

  // Empties the registry but keeps its buffers, so a reused registry does
  // not allocate again.
  void clear() {
    data_.clear();
    hashes_.clear();
    table_.assign(kMinSlots, 0);
  }

 private:
  static constexpr size_t kMinSlots = 64;
  static constexpr uint64_t kTagMask = ~uint64_t{0xffffffff};  // upper hash half; lower half = id + 1
  static int slot_id(uint64_t e) { return static_cast<int>(static_cast<uint32_t>(e)) - 1; }

  bool same(const uint64_t* a, const uint64_t* b) const {
    // States are a handful of words: a plain loop beats a memcmp call.
    for (int w = 0; w < words_; ++w)
      if (a[w] != b[w]) return false;
    return true;
  }

  void grow() {
    spare_.assign(table_.size() * 2, 0);
    const size_t mask = spare_.size() - 1;
    for (int id = 0; id < size(); ++id) {
      size_t i = hashes_[id] & mask;
      while (spare_[i] != 0) i = (i + 1) & mask;
      spare_[i] = (hashes_[id] & kTagMask) | static_cast<uint64_t>(id + 1);
    }
    table_.swap(spare_);
  }

  int words_;
  std::vector<uint64_t> data_;
  std::vector<uint64_t> hashes_;
  std::vector<uint64_t> table_;  // 0 = empty, else tag | (id + 1)
  std::vector<uint64_t> spare_;  // the previous table, reused by grow()
};

template <class T>
class StateMap {
 public:
  explicit StateMap(int words = 0) : reg_(words) {}
  int size() const { return reg_.size(); }
  uint64_t hash(const uint64_t* s) const { return reg_.hash(s); }
  const T* find(const uint64_t* s) const { return find_hashed(s, hash(s)); }
  T* find(const uint64_t* s) { return find_hashed(s, hash(s)); }
  const T* find_hashed(const uint64_t* s, uint64_t h) const {
    int id = reg_.find_hashed(s, h);
    return id < 0 ? nullptr : &vals_[id];
  }
  T* find_hashed(const uint64_t* s, uint64_t h) {
    int id = reg_.find_hashed(s, h);
    return id < 0 ? nullptr : &vals_[id];
  }
  bool contains(const uint64_t* s) const { return reg_.find(s) >= 0; }
  // Id access, for callers that keep ids instead of states (ids are stable,
  // in insertion order; references from at() die with the next insertion).
  int find_id(const uint64_t* s) const { return reg_.find(s); }
  int insert_id(const uint64_t* s, bool* added = nullptr) {
    bool is_new = false;
    const int id = reg_.insert(s, &is_new);
    if (is_new) vals_.emplace_back();
    if (added) *added = is_new;
    return id;
  }
  T& at(int id) { return vals_[static_cast<size_t>(id)]; }
  const T& at(int id) const { return vals_[static_cast<size_t>(id)]; }
  const uint64_t* key(int id) const { return reg_.get(id); }
  // Every stored value, in insertion order (states themselves are not exposed).
  std::vector<T>& values() { return vals_; }
  T& operator[](const uint64_t* s) { return insert_hashed(s, hash(s)); }
  // operator[] with a precomputed hash; *added tells whether `s` was new.
  T& insert_hashed(const uint64_t* s, uint64_t h, bool* added = nullptr) {
    bool is_new = false;
    int id = reg_.insert_hashed(s, h, &is_new);
    if (is_new) vals_.emplace_back();
    if (added) *added = is_new;
    return vals_[id];
  }
  // Sets the value only when the state is new; returns the stored value.
  T& try_emplace(const uint64_t* s, const T& v) {
    bool added = false;
    int id = reg_.insert(s, &added);
    if (added) vals_.push_back(v);
    return vals_[id];
  }
  void clear() {
    reg_.clear();
    vals_.clear();
  }

 private:
  StateRegistry reg_;
  std::vector<T> vals_;
};

}  // namespace clips::search
