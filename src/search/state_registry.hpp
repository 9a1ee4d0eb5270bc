#pragma once
// StateRegistry: states packed side by side in one array, each identified by
// a small integer id (Fast Downward's idea). Search nodes, value tables and
// reusable trees hold ids, never copies of state words.
// StateMap<T>: a registry plus one T per id.
#include <cstdint>
#include <cstring>
#include <vector>

#include "pddl/state.hpp"

namespace clips::search {

class StateRegistry {
 public:
  explicit StateRegistry(int words = 0) : words_(words) { table_.assign(64, -1); }

  int words() const { return words_; }
  int size() const { return static_cast<int>(hashes_.size()); }
  const uint64_t* get(int id) const { return data_.data() + static_cast<size_t>(id) * words_; }
  pddl::State state(int id) const { return pddl::State{std::vector<uint64_t>(get(id), get(id) + words_)}; }

  int find(const uint64_t* s) const {
    uint64_t h = pddl::hash_words(s, words_);
    size_t mask = table_.size() - 1;
    for (size_t i = h & mask;; i = (i + 1) & mask) {
      int id = table_[i];
      if (id < 0) return -1;
      if (hashes_[id] == h && std::memcmp(get(id), s, sizeof(uint64_t) * words_) == 0) return id;
    }
  }

  // Returns the id of `s`, adding it if new (then *added is set).
  int insert(const uint64_t* s, bool* added = nullptr) {
    uint64_t h = pddl::hash_words(s, words_);
    size_t mask = table_.size() - 1;
    size_t i = h & mask;
    for (;; i = (i + 1) & mask) {
      int id = table_[i];
      if (id < 0) break;
      if (hashes_[id] == h && std::memcmp(get(id), s, sizeof(uint64_t) * words_) == 0) {
        if (added) *added = false;
        return id;
      }
    }
    int id = size();
    data_.insert(data_.end(), s, s + words_);
    hashes_.push_back(h);
    table_[i] = id;
    if (added) *added = true;
    if (static_cast<size_t>(size()) * 2 > table_.size()) grow();
    return id;
  }

  void clear() {
    data_.clear();
    hashes_.clear();
    table_.assign(64, -1);
  }

 private:
  void grow() {
    std::vector<int> t(table_.size() * 2, -1);
    size_t mask = t.size() - 1;
    for (int id = 0; id < size(); ++id) {
      size_t i = hashes_[id] & mask;
      while (t[i] >= 0) i = (i + 1) & mask;
      t[i] = id;
    }
    table_.swap(t);
  }

  int words_;
  std::vector<uint64_t> data_;
  std::vector<uint64_t> hashes_;
  std::vector<int> table_;
};

template <class T>
class StateMap {
 public:
  explicit StateMap(int words = 0) : reg_(words) {}
  int size() const { return reg_.size(); }
  const T* find(const uint64_t* s) const {
    int id = reg_.find(s);
    return id < 0 ? nullptr : &vals_[id];
  }
  T* find(const uint64_t* s) {
    int id = reg_.find(s);
    return id < 0 ? nullptr : &vals_[id];
  }
  bool contains(const uint64_t* s) const { return reg_.find(s) >= 0; }
  T& operator[](const uint64_t* s) {
    bool added = false;
    int id = reg_.insert(s, &added);
    if (added) vals_.emplace_back();
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
