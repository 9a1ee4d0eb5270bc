#include "domains/dkg/dkg_map.hpp"

#include <algorithm>
#include <deque>

#include "util/error.hpp"

namespace clips::domains::dkg {

using pddl::ObjectId;

namespace {

std::vector<ObjectId> sorted_by_name(const pddl::Task& t, std::vector<ObjectId> v) {
  std::sort(v.begin(), v.end(), [&](ObjectId a, ObjectId b) { return t.object_name(a) < t.object_name(b); });
  return v;
}

int find_index(const std::vector<int>& v, int x) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i] == x) return static_cast<int>(i);
  return -1;
}

// COMPATIBLE((K1,D1),(K2,D2)): every pair of the second set is either the
// same aligned pair in the first one, or entirely new.
bool compatible(const KeyDoorSet& a, const KeyDoorSet& b) {
  for (size_t j = 0; j < b.keys.size(); ++j)
    if (find_index(a.keys, b.keys[j]) != find_index(a.doors, b.doors[j])) return false;
  return true;
}

// Order-preserving union; alignment survives because compatible() holds.
KeyDoorSet unite(const KeyDoorSet& a, const KeyDoorSet& b) {
  KeyDoorSet out = a;
  for (int k : b.keys)
    if (find_index(out.keys, k) < 0) out.keys.push_back(k);
  for (int d : b.doors)
    if (find_index(out.doors, d) < 0) out.doors.push_back(d);
  return out;
}

void dedupe_keep_first(KeyDoorSets& s) {
  KeyDoorSets out;
  out.reserve(s.size());
  for (auto& x : s)
    if (std::find(out.begin(), out.end(), x) == out.end()) out.push_back(std::move(x));
  s = std::move(out);
}

bool is_trivial(const KeyDoorSets& s) { return s.size() == 1 && s[0].keys.empty(); }

}  // namespace

std::shared_ptr<const DkgMapAnalysis> DkgMapAnalysis::build(std::shared_ptr<const pddl::Task> task,
                                                            const pddl::State& state) {
  std::shared_ptr<DkgMapAnalysis> m(new DkgMapAnalysis());
  const pddl::Task& t = *task;
  m->task_ = std::move(task);

  auto walls = t.fluent("walls", {});
  if (!walls.matrix) throw InputError("Doors-Keys-Gems heuristic: the task has no static (walls) bit-matrix");
  m->width_ = walls.matrix->cols;
  m->height_ = walls.matrix->rows;

  auto agents = sorted_by_name(t, t.objects_of_type("agent"));
  auto items = sorted_by_name(t, t.objects_of_type("item"));
  auto doors = sorted_by_name(t, t.objects_of_type("door"));
  m->num_agents_ = static_cast<int>(agents.size());
  m->num_items_ = static_cast<int>(items.size());
  m->num_doors_ = static_cast<int>(doors.size());
  m->objects_ = agents;
  m->objects_.insert(m->objects_.end(), items.begin(), items.end());
  m->objects_.insert(m->objects_.end(), doors.begin(), doors.end());
  if (m->objects_.size() > static_cast<size_t>(kObjMaskBits))
    throw InputError("Doors-Keys-Gems heuristic: the map has " + std::to_string(m->objects_.size()) +
                     " agents, items and doors; at most " + std::to_string(kObjMaskBits) + " are supported");
  m->index_.assign(t.num_objects(), -1);
  const int n = m->num_objects();
  for (int i = 0; i < n; ++i) {
    ObjectId o = m->objects_[i];
    m->index_[o] = i;
    m->kind_.push_back(i < m->num_agents_                     ? Kind::Agent
                       : i >= m->first_door()                 ? Kind::Door
                       : t.object_is_a(o, "key")              ? Kind::Key
                                                              : Kind::Gem);
    m->x_.push_back(t.fluent("xloc", {t.object_name(o)}));
    m->y_.push_back(t.fluent("yloc", {t.object_name(o)}));
  }
  for (int i = m->num_agents_; i < m->first_door(); ++i)
    for (int a = 0; a < m->num_agents_; ++a) m->has_.push_back(t.atom("has", {m->name(a), m->name(i)}));
  for (int d = m->first_door(); d < n; ++d) m->locked_.push_back(t.atom("locked", {m->name(d)}));
  for (int a = 0; a < m->num_agents_; ++a) m->active_.push_back(t.atom("active", {m->name(a)}));

  // Unlockers: every key sharing a colour with the door.
  auto colors = t.objects_of_type("color");
  auto same_color = [&](int i, int j) {
    for (ObjectId c : colors)
      if (t.atom("iscolor", {m->name(i), t.object_name(c)}).value &&
          t.atom("iscolor", {m->name(j), t.object_name(c)}).value)
        return true;
    return false;
  };
  for (int d = m->first_door(); d < n; ++d) {
    std::vector<int> ks;
    for (int k = m->num_agents_; k < m->first_door(); ++k)
      if (m->kind_[k] == Kind::Key && same_color(k, d)) ks.push_back(k);
    m->unlockers_.push_back(std::move(ks));
  }

  // Room labelling: walls plus door cells block; 4-connected components.
  // Cells are visited column by column (the reference's column-major matrix
  // order) so the numbering, and hence the path enumeration order, matches.
  const int W = m->width_, H = m->height_, N = W * H;
  auto wall_at = [&](int x, int y) { return walls.matrix->get(y - 1, x - 1); };
  std::vector<uint8_t> blocked(N, 0);
  for (int y = 1; y <= H; ++y)
    for (int x = 1; x <= W; ++x) blocked[m->cell(x, y)] = wall_at(x, y);
  std::vector<int> door_cell;
  for (int d = m->first_door(); d < n; ++d) {
    int x = static_cast<int>(t.value(state, m->x_[d])), y = static_cast<int>(t.value(state, m->y_[d]));
    if (x < 1 || y < 1 || x > W || y > H)
      throw InputError(SourceLoc{t.problem().file, 0, 0},
                       "Doors-Keys-Gems heuristic: door " + m->name(d) + " is off the grid");
    door_cell.push_back(m->cell(x, y));
    blocked[m->cell(x, y)] = 1;
  }
  m->labels_.assign(N, 0);
  const int dx[4] = {0, 0, -1, 1}, dy[4] = {-1, 1, 0, 0};  // up, down, left, right
  int next_label = 1;
  std::vector<int> stack;
  for (int x = 1; x <= W; ++x)
    for (int y = 1; y <= H; ++y) {
      int c = m->cell(x, y);
      if (blocked[c] || m->labels_[c]) continue;
      m->labels_[c] = next_label;
      stack.assign(1, c);
      while (!stack.empty()) {
        int cur = stack.back();
        stack.pop_back();
        int cx = cur % W + 1, cy = cur / W + 1;
        for (int k = 0; k < 4; ++k) {
          int nx = cx + dx[k], ny = cy + dy[k];
          if (nx < 1 || ny < 1 || nx > W || ny > H) continue;
          int nc = m->cell(nx, ny);
          if (blocked[nc] || m->labels_[nc]) continue;
          m->labels_[nc] = next_label;
          stack.push_back(nc);
        }
      }
      ++next_label;
    }
  m->num_rooms_ = next_label - 1;
  for (int i = 0; i < m->num_doors_; ++i) m->labels_[door_cell[i]] = m->num_rooms_ + 1 + i;

  // Room graph: each door is linked to every labelled 4-neighbour (rooms and
  // adjacent doors alike).
  const int L = m->num_labels();
  m->room_adj_.assign(L, {});
  for (int i = 0; i < m->num_doors_; ++i) {
    int c = door_cell[i], cx = c % W + 1, cy = c / W + 1, dl = m->num_rooms_ + 1 + i;
    for (int k = 0; k < 4; ++k) {
      int nx = cx + dx[k], ny = cy + dy[k];
      if (nx < 1 || ny < 1 || nx > W || ny > H) continue;
      int l = m->labels_[m->cell(nx, ny)];
      if (l == 0 || l == dl) continue;
      auto& a = m->room_adj_[dl];
      if (std::find(a.begin(), a.end(), l) == a.end()) {
        a.push_back(l);
        m->room_adj_[l].push_back(dl);
      }
    }
  }
  for (auto& a : m->room_adj_) std::sort(a.begin(), a.end());
  m->adj_.assign(static_cast<size_t>(L) * L, 0);
  m->share_.assign(static_cast<size_t>(L) * L, 0);
  for (int l = 0; l < L; ++l)
    for (int r : m->room_adj_[l]) m->adj_[l * L + r] = 1;
  for (int l1 = 0; l1 < L; ++l1)
    for (int l2 = 0; l2 < L; ++l2)
      for (int r : m->room_adj_[l1])
        if (m->adj_[l2 * L + r]) {
          m->share_[l1 * L + l2] = 1;
          break;
        }

  // All-pairs BFS distances over non-wall cells; doors do not block here.
  m->dist_.assign(static_cast<size_t>(N) * N, kNoPath);
  std::vector<int> queue(N);
  for (int s = 0; s < N; ++s) {
    if (wall_at(s % W + 1, s / W + 1)) continue;
    uint16_t* row = &m->dist_[static_cast<size_t>(s) * N];
    row[s] = 0;
    int head = 0, tail = 0;
    queue[tail++] = s;
    while (head < tail) {
      int cur = queue[head++];
      int cx = cur % W + 1, cy = cur / W + 1;
      for (int k = 0; k < 4; ++k) {
        int nx = cx + dx[k], ny = cy + dy[k];
        if (nx < 1 || ny < 1 || nx > W || ny > H || wall_at(nx, ny)) continue;
        int nc = m->cell(nx, ny);
        if (row[nc] != kNoPath) continue;
        row[nc] = static_cast<uint16_t>(row[cur] + 1);
        queue[tail++] = nc;
      }
    }
  }

  // MST edge admission by room labels (as the reference), per cell pair, so the
  // heuristic reads one table entry per object pair: same label or
  // neighbouring labels; for two doors also a common neighbouring room.
  m->edge_.assign(static_cast<size_t>(N) * N, kNoPath);
  m->door_edge_.assign(static_cast<size_t>(N) * N, kNoPath);
  for (int c1 = 0; c1 < N; ++c1)
    for (int c2 = 0; c2 < N; ++c2) {
      const size_t k = static_cast<size_t>(c1) * N + c2;
      const uint16_t d = m->dist_[k];
      if (d == kNoPath) continue;
      const int l1 = m->labels_[c1], l2 = m->labels_[c2];
      const bool near = l1 == l2 || m->room_adjacent(l1, l2);
      if (near) m->edge_[k] = d;
      if (near || m->share_neighbor(l1, l2)) m->door_edge_[k] = d;
    }
  return m;
}

void DkgMapAnalysis::read(const uint64_t* s, DkgStateView& out) const {
  const int n = num_objects();
  out.cell.resize(n);
  out.room.resize(n);
  out.holder.resize(n);
  const int base = task_->fluent_base();
  auto val = [&](const pddl::Task::FluentRef& f) -> int {
    return f.slot < 0 ? static_cast<int>(f.value) : pddl::get_num(s, base, f.slot);
  };
  auto test = [&](const pddl::Task::AtomRef& a) { return a.bit < 0 ? a.value : pddl::get_bit(s, a.bit); };
  for (int i = 0; i < n; ++i) {
    int x = val(x_[i]), y = val(y_[i]);
    out.holder[i] = -1;
    if (x < 1 || y < 1) {
      out.cell[i] = -1;
      if (i >= num_agents_ && i < first_door()) {
        const auto* h = &has_[static_cast<size_t>(i - num_agents_) * num_agents_];
        for (int a = 0; a < num_agents_; ++a)
          if (test(h[a])) {
            // Agents come first, so their cells are already known.
            out.cell[i] = out.cell[a];
            out.holder[i] = static_cast<int8_t>(a);
            break;
          }
      }
    } else {
      out.cell[i] = cell(x, y);
    }
    out.room[i] = out.cell[i] >= 0 ? labels_[out.cell[i]] : 0;
  }
  out.locked = 0;
  for (int d = 0; d < num_doors_; ++d)
    if (test(locked_[d])) out.locked |= mask_bit(d);
  out.active = -1;
  for (int a = 0; a < num_agents_; ++a)
    if (test(active_[a])) {
      out.active = a;
      break;
    }
}

KeyDoorSets DkgMapAnalysis::pathsets(int r0, int g) const {
  KeyDoorSets out;
  if (r0 == g) {
    out.push_back({});
    return out;
  }
  if (r0 <= 0 || g <= 0) return out;
  // Breadth-first enumeration of all simple paths r0 -> g, neighbours in
  // ascending label order (the reference's order).
  std::deque<std::vector<int>> queue;
  queue.push_back({r0});
  std::vector<int> doors, choice, keys;
  KeyDoorSets from_path;
  while (!queue.empty()) {
    std::vector<int> path = std::move(queue.front());
    queue.pop_front();
    int u = path.back();
    if (u == g) {
      doors.clear();
      for (int l : path)
        if (l > num_rooms_) doors.push_back(first_door() + (l - num_rooms_ - 1));
      // One unlocker per door, all distinct; the first door's key varies
      // fastest (Julia's Iterators.product order); duplicates dropped.
      from_path.clear();
      bool feasible = true;
      for (int d : doors) feasible = feasible && !unlockers(d).empty();
      if (feasible) {
        choice.assign(doors.size(), 0);
        while (true) {
          keys.clear();
          bool distinct = true;
          for (size_t j = 0; j < doors.size(); ++j) {
            int k = unlockers(doors[j])[choice[j]];
            if (find_index(keys, k) >= 0) distinct = false;
            keys.push_back(k);
          }
          if (distinct) {
            KeyDoorSet kd{keys, doors};
            if (std::find(from_path.begin(), from_path.end(), kd) == from_path.end()) from_path.push_back(kd);
          }
          size_t j = 0;
          while (j < doors.size() && ++choice[j] == static_cast<int>(unlockers(doors[j]).size())) choice[j++] = 0;
          if (j == doors.size()) break;
        }
      }
      for (auto& kd : from_path) out.push_back(std::move(kd));
      continue;
    }
    for (int v : room_adj_[u]) {
      if (find_index(path, v) >= 0) continue;
      std::vector<int> next = path;
      next.push_back(v);
      queue.push_back(std::move(next));
    }
  }
  return out;
}

KeyDoorSets DkgMapAnalysis::necessary(const DkgStateView& v, int agent, std::span<const int> targets) const {
  const int r0 = v.room[agent];
  std::vector<int> goals;
  for (int x : targets) {
    if (v.cell[x] < 0) continue;  // consumed key: nowhere to go
    if (find_index(goals, v.room[x]) < 0) goals.push_back(v.room[x]);
  }
  if (goals.empty() || std::all_of(goals.begin(), goals.end(), [&](int g) { return g == r0; }))
    return KeyDoorSets{KeyDoorSet{}};
  KeyDoorSets s = pathsets(r0, goals[0]);
  for (size_t gi = 1; gi < goals.size(); ++gi) {
    KeyDoorSets more = pathsets(r0, goals[gi]), merged;
    // Julia's Iterators.product(S, more): S varies fastest.
    for (const auto& b : more)
      for (const auto& a : s)
        if (compatible(a, b)) merged.push_back(unite(a, b));
    s = std::move(merged);
  }
  return s;
}

KeyDoorSets DkgMapAnalysis::recursive(const DkgStateView& v, int agent, std::span<const int> targets,
                                      int max_iters) const {
  KeyDoorSets s = necessary(v, agent, targets);
  if (is_trivial(s)) return s;
  std::vector<int> need;
  for (int iter = 0; iter < max_iters; ++iter) {
    bool added = false;
    KeyDoorSets next;
    for (size_t i = 0; i < s.size(); ++i) {
      const KeyDoorSet& kd = s[i];
      need.clear();
      for (size_t j = 0; j < kd.keys.size(); ++j)
        if (locked(v, kd.doors[j])) need.push_back(kd.keys[j]);
      // Quirk kept from the reference: once a set needing extra keys has been
      // found, later sets with nothing locked are dropped here.
      if (need.empty()) continue;
      KeyDoorSets sub = necessary(v, agent, need);
      if (!added) {
        if (is_trivial(sub)) continue;
        next.assign(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(i));
        added = true;
      }
      for (const auto& b : sub)
        if (compatible(kd, b)) next.push_back(unite(kd, b));
    }
    if (!added) break;
    dedupe_keep_first(next);
    if (next == s) break;
    s = std::move(next);
  }
  return s;
}

}  // namespace clips::domains::dkg
