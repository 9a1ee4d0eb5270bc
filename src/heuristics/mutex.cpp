#include "heuristics/mutex.hpp"

#include "heuristics/conditions.hpp"

#include <algorithm>
#include <map>
#include <mutex>

namespace clips::heuristics {

MutexTable::MutexTable(const pddl::Task& task, int max_atoms) {
  const int n = task.num_atoms();
  if (n == 0 || n > max_atoms) return;
  empty_ = false;
  words_ = (static_cast<size_t>(n) + 63) / 64;
  rows_.assign(static_cast<size_t>(n) * words_, 0);
  auto row = [&](int p) { return rows_.data() + static_cast<size_t>(p) * words_; };
  auto set = [&](int p, int q) -> bool {
    uint64_t& w = row(p)[static_cast<size_t>(q) >> 6];
    const uint64_t m = uint64_t{1} << (q & 63);
    if (w & m) return false;
    w |= m;
    row(q)[static_cast<size_t>(p) >> 6] |= uint64_t{1} << (p & 63);
    return true;
  };
  const pddl::State s0 = task.initial_state();
  std::vector<int> init;
  for (int b = 0; b < n; ++b)
    if (pddl::get_bit(s0.data(), b)) init.push_back(b);
  for (int p : init)
    for (int q : init) set(p, q);
  // Derived atoms follow from the others, not from actions: never mutex.
  for (int p = 0; p < n; ++p)
    if (task.is_derived(p))
      for (int q = 0; q < n; ++q) set(p, q);

  struct Op {
    std::vector<int> pre, add;
    std::vector<uint64_t> del;  // bit set
  };
  std::vector<Op> ops;
  for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
    const auto& ga = task.action(a);
    Op o;
    conjuncts(task, ga.pre, o.pre);
    std::sort(o.pre.begin(), o.pre.end());
    o.pre.erase(std::unique(o.pre.begin(), o.pre.end()), o.pre.end());
    o.add = ga.eff.add;
    for (const auto& ce : ga.cond_eff) o.add.insert(o.add.end(), ce.eff.add.begin(), ce.eff.add.end());
    std::sort(o.add.begin(), o.add.end());
    o.add.erase(std::unique(o.add.begin(), o.add.end()), o.add.end());
    if (o.add.empty()) continue;
    o.del.assign(words_, 0);
    for (int b : ga.eff.del) o.del[static_cast<size_t>(b) >> 6] |= uint64_t{1} << (b & 63);
    ops.push_back(std::move(o));
  }
  // Fixpoint: an operator whose preconditions are pairwise reachable makes
  // its adds reachable together, and each add together with every atom that
  // can hold with all its preconditions and that it does not delete.
  std::vector<uint64_t> compatible(words_);
  for (bool changed = true; changed;) {
    changed = false;
    for (const Op& o : ops) {
      bool ok = true;
      for (size_t i = 0; i < o.pre.size() && ok; ++i)
        for (size_t j = i; j < o.pre.size() && ok; ++j) ok = reach2(o.pre[i], o.pre[j]);
      if (!ok) continue;
      std::fill(compatible.begin(), compatible.end(), ~uint64_t{0});
      for (int r : o.pre)
        for (size_t w = 0; w < words_; ++w) compatible[w] &= row(r)[w];
      if (o.pre.empty()) {
        // No precondition: anything reachable may persist.
        std::fill(compatible.begin(), compatible.end(), 0);
        for (int b = 0; b < n; ++b)
          if (reach1(b)) compatible[static_cast<size_t>(b) >> 6] |= uint64_t{1} << (b & 63);
      }
      for (size_t w = 0; w < words_; ++w) compatible[w] &= ~o.del[w];
      for (int e : o.add) {
        for (int e2 : o.add) changed |= set(e, e2);
        uint64_t* re = row(e);
        for (size_t w = 0; w < words_; ++w) {
          const uint64_t fresh = compatible[w] & ~re[w];
          if (!fresh) continue;
          changed = true;
          for (uint64_t bits = fresh; bits; bits &= bits - 1) set(e, static_cast<int>(w * 64 + __builtin_ctzll(bits)));
        }
      }
    }
  }
}

bool MutexTable::any_mutex(const std::vector<int>& atoms) const {
  if (empty_) return false;
  for (size_t i = 0; i < atoms.size(); ++i)
    for (size_t j = i + 1; j < atoms.size(); ++j)
      if (mutex(atoms[i], atoms[j])) return true;
  return false;
}

std::shared_ptr<const MutexTable> MutexTable::of(const std::shared_ptr<const pddl::Task>& task, int max_atoms) {
  // One table per live task; entries of tasks that are gone are dropped.
  static std::mutex mu;
  static std::map<const pddl::Task*, std::pair<std::weak_ptr<const pddl::Task>, std::shared_ptr<const MutexTable>>>
      cache;
  {
    std::lock_guard lock(mu);
    auto it = cache.find(task.get());
    if (it != cache.end() && it->second.first.lock() == task) return it->second.second;
  }
  auto table = std::make_shared<const MutexTable>(*task, max_atoms);
  std::lock_guard lock(mu);
  for (auto it = cache.begin(); it != cache.end();)
    it = it->second.first.expired() ? cache.erase(it) : std::next(it);
  cache[task.get()] = {task, table};
  return table;
}

}  // namespace clips::heuristics
