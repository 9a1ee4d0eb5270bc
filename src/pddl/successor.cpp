// Successor generation of a Task: preconditions flattened into primitive
// tests, actions cut into trigger-group chunks with literal filters, and the
// remaining conjuncts recompiled for the generator (see task.hpp). Built once
// at the end of grounding, read-only afterwards.
#include <algorithm>
#include <map>

#include "pddl/task.hpp"
#include "pddl/task_inline.hpp"

namespace clips::pddl {

void Task::flatten_preconditions() {
  prims_.clear();
  rests_.clear();
  prim_begin_.assign(1, 0);
  rest_begin_.assign(1, 0);
  auto primitive = [](const CNode& n) {
    return n.op == CNode::Atom || n.op == CNode::NotAtom || n.op == CNode::SlotConst || n.op == CNode::SlotSlot ||
           n.op == CNode::False;
  };
  for (const GroundAction& g : actions_) {
    const CNode& root = pool_.cnodes[g.pre];
    std::vector<CondId> kids;
    if (root.op == CNode::And)
      for (int i = 0; i < root.b; ++i) kids.push_back(pool_.ckids[root.a + i]);
    else if (root.op != CNode::True)
      kids.push_back(g.pre);
    for (CondId k : kids) {
      if (primitive(pool_.cnodes[k])) prims_.push_back(pool_.cnodes[k]);
      else rests_.push_back(k);
    }
    prim_begin_.push_back(static_cast<int>(prims_.size()));
    rest_begin_.push_back(static_cast<int>(rests_.size()));
  }
  build_chunks();
}

void Task::build_chunks() {
  chunks_.clear();
  chunk_actions_.clear();
  lit_filters_.clear();
  gen_prims_.clear();
  gen_begin_.assign(1, 0);
  gnodes_.clear();
  gkids_.clear();
  gprims_.clear();
  cells_.clear();
  gen_rests_.clear();
  for (CondId r : rests_) gen_rests_.push_back(compile_gen(r));
  // Literal filters replace every atom test, so survivors only compare slots.
  for (ActionId a = 0; a < num_actions(); ++a) {
    for (int i = prim_begin_[a]; i < prim_begin_[a + 1]; ++i)
      if (prims_[i].op != CNode::Atom && prims_[i].op != CNode::NotAtom) gen_prims_.push_back(prims_[i]);
    gen_begin_.push_back(static_cast<int>(gen_prims_.size()));
  }
  auto add_chunks = [&](int trigger, const std::vector<ActionId>& acts) {
    for (size_t first = 0; first < acts.size(); first += 64) {
      Chunk c;
      c.trigger = trigger;
      c.first = static_cast<int>(chunk_actions_.size());
      c.count = static_cast<int>(std::min<size_t>(64, acts.size() - first));
      c.lit_begin = static_cast<int>(lit_filters_.size());
      std::map<int, LitFilter> lits;  // by bit, so filters run in bit order
      for (int j = 0; j < c.count; ++j) {
        ActionId a = acts[first + j];
        chunk_actions_.push_back(a);
        for (int i = prim_begin_[a]; i < prim_begin_[a + 1]; ++i) {
          const CNode& n = prims_[i];
          if (n.op != CNode::Atom && n.op != CNode::NotAtom) continue;
          if (n.op == CNode::Atom && n.a == trigger) continue;  // the chunk's own test
          LitFilter& f = lits[n.a];
          f.bit = n.a;
          (n.op == CNode::Atom ? f.kill_if_clear : f.kill_if_set) |= uint64_t{1} << j;
        }
      }
      for (const auto& [bit, f] : lits) lit_filters_.push_back(f);
      c.lit_end = static_cast<int>(lit_filters_.size());
      chunks_.push_back(c);
    }
  };
  for (const auto& [bit, acts] : trigger_groups_) add_chunks(bit, acts);
  add_chunks(-1, untriggered_);
}

bool Task::applicable_rest(ActionId a, const uint64_t* s) const {
  for (int i = gen_begin_[a], e = gen_begin_[a + 1]; i < e; ++i)
    if (!test_prim(gen_prims_[i], s)) return false;
  for (int i = rest_begin_[a], e = rest_begin_[a + 1]; i < e; ++i)
    if (!eval_gen(gen_rests_[i], s)) return false;
  return true;
}

int Task::compile_gen(CondId c) {
  const CNode& n = pool_.cnodes[c];
  GNode g;
  switch (n.op) {
    case CNode::Atom: case CNode::NotAtom: case CNode::False: case CNode::SlotConst: case CNode::SlotSlot:
      g.op = GNode::Prim;
      g.prim = n;
      break;
    case CNode::And:
    case CNode::Or: {
      std::vector<int> kids;
      for (int i = 0; i < n.b; ++i) kids.push_back(compile_gen(pool_.ckids[n.a + i]));
      if (n.op == CNode::And && std::all_of(kids.begin(), kids.end(), [&](int k) { return gnodes_[k].op == GNode::Prim; })) {
        // A conjunction of primitives: one flat loop, no recursion.
        g.op = GNode::Prims;
        g.a = static_cast<int>(gprims_.size());
        g.b = n.b;
        for (int k : kids) gprims_.push_back(gnodes_[k].prim);
        break;
      }
      g.op = n.op == CNode::And ? GNode::And : GNode::Or;
      g.a = static_cast<int>(gkids_.size());
      g.b = n.b;
      gkids_.insert(gkids_.end(), kids.begin(), kids.end());
      break;
    }
    case CNode::Not:
      g.op = GNode::Not;
      g.a = compile_gen(n.a);
      break;
    case CNode::Eq: case CNode::Ne: case CNode::Lt: case CNode::Le: case CNode::Gt: case CNode::Ge: {
      static const CNode::Op mirror[] = {CNode::Eq, CNode::Ne, CNode::Gt, CNode::Ge, CNode::Lt, CNode::Le};
      int m = n.a, k = n.b;
      CNode::Op op = n.op;
      if (pool_.nnodes[m].op != NNode::GetIndex) {
        std::swap(m, k);
        op = mirror[op - CNode::Eq];
      }
      // coordinate: fluent (+k) or constant
      auto coord = [&](int x, int& slot, int& off) {
        const NNode& v = pool_.nnodes[x];
        if (v.op == NNode::Const && v.v >= INT32_MIN && v.v <= INT32_MAX) return off = static_cast<int>(v.v), slot = -1, true;
        if (v.op == NNode::Fluent) return slot = static_cast<int>(v.v), off = v.a, true;
        return false;
      };
      CellTest t;
      if (pool_.nnodes[m].op == NNode::GetIndex && pool_.nnodes[k].op == NNode::Const &&
          coord(pool_.nnodes[m].a, t.row_slot, t.row_k) && coord(pool_.nnodes[m].b, t.col_slot, t.col_k)) {
        t.matrix = static_cast<int>(pool_.nnodes[m].v);
        t.cmp = op;
        t.value = pool_.nnodes[k].v;
        g.op = GNode::Cell;
        g.a = static_cast<int>(cells_.size());
        cells_.push_back(t);
        break;
      }
      g.op = GNode::Cond;
      g.a = c;
      break;
    }
    default:
      g.op = GNode::Cond;
      g.a = c;
  }
  gnodes_.push_back(g);
  return static_cast<int>(gnodes_.size()) - 1;
}

bool Task::eval_gen(int gi, const uint64_t* s) const {
  const GNode& g = gnodes_[gi];
  switch (g.op) {
    case GNode::Prim: return test_prim(g.prim, s);
    case GNode::Prims:
      for (int i = g.a, e = g.a + g.b; i < e; ++i)
        if (!test_prim(gprims_[i], s)) return false;
      return true;
    case GNode::And:
      for (int i = 0; i < g.b; ++i)
        if (!eval_gen(gkids_[g.a + i], s)) return false;
      return true;
    case GNode::Or:
      for (int i = 0; i < g.b; ++i)
        if (eval_gen(gkids_[g.a + i], s)) return true;
      return false;
    case GNode::Not: return !eval_gen(g.a, s);
    case GNode::Cell: {
      const CellTest& t = cells_[g.a];
      const BitMatrix& m = matrices_[t.matrix];
      // Same arithmetic as eval_num on the GetIndex node.
      int64_t r = t.row_slot < 0 ? t.row_k : int64_t{get_num(s, atom_words_, t.row_slot)} + t.row_k;
      int64_t c = t.col_slot < 0 ? t.col_k : int64_t{get_num(s, atom_words_, t.col_slot)} + t.col_k;
      int64_t x = (r < 1 || r > m.rows || c < 1 || c > m.cols) ? -1 : m.get(static_cast<int>(r - 1), static_cast<int>(c - 1));
      return detail::compare(x, t.cmp - CNode::Eq, t.value);
    }
    case GNode::Cond: return eval(g.a, s);
  }
  return false;
}

bool Task::applicable(ActionId a, const uint64_t* s) const {
  for (int i = prim_begin_[a], e = prim_begin_[a + 1]; i < e; ++i)
    if (!test_prim(prims_[i], s)) return false;
  for (int i = rest_begin_[a], e = rest_begin_[a + 1]; i < e; ++i)
    if (!eval(rests_[i], s)) return false;
  return true;
}

void Task::applicable_actions(const uint64_t* s, std::vector<ActionId>& out) const {
  out.clear();
  int sources = 0;
  for (const Chunk& c : chunks_) {
    if (c.trigger >= 0 && !get_bit(s, c.trigger)) continue;
    uint64_t live = c.count == 64 ? ~uint64_t{0} : (uint64_t{1} << c.count) - 1;
    for (int i = c.lit_begin; i < c.lit_end && live; ++i) {
      const LitFilter& f = lit_filters_[i];
      live &= ~(get_bit(s, f.bit) ? f.kill_if_set : f.kill_if_clear);
    }
    if (!live) continue;
    ++sources;
    const ActionId* acts = &chunk_actions_[c.first];
    for (; live; live &= live - 1) {
      ActionId a = acts[__builtin_ctzll(live)];
      if (applicable_rest(a, s)) out.push_back(a);
    }
  }
  // Each chunk lists its actions in ascending order; several must be merged.
  if (sources > 1) std::sort(out.begin(), out.end());
}

std::vector<ActionId> Task::applicable_actions(const State& s) const {
  std::vector<ActionId> out;
  applicable_actions(s.data(), out);
  return out;
}

}  // namespace clips::pddl
