#pragma once
// Internals shared by the grounder, the runtime and the successor generator
// of Task (not part of the public interface).
#include <cstdint>
#include <vector>

#include "pddl/task.hpp"

namespace clips::pddl {
namespace detail {

// [head, args...]: the key of a ground atom, fluent or action in the tables.
inline std::vector<int> key_of(int head, const std::vector<ObjectId>& args) {
  std::vector<int> k;
  k.reserve(args.size() + 1);
  k.push_back(head);
  k.insert(k.end(), args.begin(), args.end());
  return k;
}

// x op y for the comparison codes Eq..Ge = 0..5 (CNode::c & 7, CNode::Op - Eq).
[[gnu::always_inline]] inline bool compare(int64_t x, int op, int64_t y) {
  switch (op) {
    case 0: return x == y;
    case 1: return x != y;
    case 2: return x < y;
    case 3: return x <= y;
    case 4: return x > y;
    default: return x >= y;
  }
}

}  // namespace detail

// Inlined into every evaluator: it is the innermost test.
[[gnu::always_inline]] inline bool Task::test_prim(const CNode& n, const uint64_t* s) const {
  switch (n.op) {
    case CNode::Atom: return get_bit(s, n.a);
    case CNode::NotAtom: return !get_bit(s, n.a);
    case CNode::False: return false;
    default: {
      const int x = get_num(s, atom_words_, n.a);
      const int y = n.op == CNode::SlotConst ? n.b : get_num(s, atom_words_, n.b) + (n.c >> 3);
      return detail::compare(x, n.c & 7, y);
    }
  }
}

}  // namespace clips::pddl
