#pragma once
// Goal-independent analysis of a Doors-Keys-Gems map for the MST heuristic
// (the reference's DoorsKeysMSTHeuristic): room labels, the room graph, door
// unlockers, all-pairs cell distances, and the NECESSARY / PATHSETS /
// RECURSIVE key-and-door analysis.
//
// One DkgMapAnalysis is built per problem from the state the first planning
// call starts from (s_0 for inference, s_T for assistance) and is immutable
// afterwards, so hypotheses and threads may share it through a shared_ptr.
//
// Objects are numbered as the reference orders them: agents sorted by name, then
// items (keys and gems) sorted by name, then doors sorted by name. Sets of
// objects are ObjMask bit masks over these indices (dkg_mask.hpp), so a map
// holds at most kObjMaskBits (128) objects.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "domains/dkg/dkg_mask.hpp"
#include "pddl/task.hpp"

namespace clips::domains::dkg {

// An aligned list of keys and the doors they open: keys[j] opens doors[j]
// (object indices). PATHSETS and NECESSARY return lists of these.
struct KeyDoorSet {
  std::vector<int> keys, doors;
  bool operator==(const KeyDoorSet& o) const { return keys == o.keys && doors == o.doors; }
};
using KeyDoorSets = std::vector<KeyDoorSet>;

// Where every object is in one state, as the heuristic sees it.
struct DkgStateView {
  std::vector<int> cell;     // loc*(o): own cell, else the holder's cell, else -1
  std::vector<int> room;     // room/door label of `cell`, 0 when cell is -1
  std::vector<int8_t> holder;  // index of the agent holding the item, -1 if none
  ObjMask locked = 0;        // bit i: door i (door order) is locked
  int active = -1;           // index of the active agent, -1 if none
};

class DkgMapAnalysis {
 public:
  enum class Kind : uint8_t { Agent, Key, Gem, Door };

  static std::shared_ptr<const DkgMapAnalysis> build(std::shared_ptr<const pddl::Task> task,
                                                     const pddl::State& state);

  const pddl::Task& task() const { return *task_; }
  const std::shared_ptr<const pddl::Task>& task_ptr() const { return task_; }

  // ---- objects (the reference's order)
  int num_objects() const { return static_cast<int>(objects_.size()); }
  int num_agents() const { return num_agents_; }
  int num_items() const { return num_items_; }
  int num_doors() const { return num_doors_; }
  int first_door() const { return num_agents_ + num_items_; }
  pddl::ObjectId object(int i) const { return objects_[i]; }
  int index_of(pddl::ObjectId o) const { return o >= 0 && o < static_cast<int>(index_.size()) ? index_[o] : -1; }
  Kind kind(int i) const { return kind_[i]; }
  const std::string& name(int i) const { return task_->object_name(objects_[i]); }
  // Keys with the door's colour (object indices, keys in name order).
  const std::vector<int>& unlockers(int door_index) const { return unlockers_[door_index - first_door()]; }

  // ---- grid
  int width() const { return width_; }
  int height() const { return height_; }
  int cell(int x, int y) const { return (y - 1) * width_ + (x - 1); }  // 1-based x, y
  int num_cells() const { return width_ * height_; }
  // Room label of a cell: 1..R rooms, R+1..R+D doors (door order), 0 walls.
  int label(int cell) const { return labels_[cell]; }
  int num_rooms() const { return num_rooms_; }
  int num_labels() const { return num_rooms_ + num_doors_ + 1; }  // including 0
  int door_label(int door_index) const { return num_rooms_ + 1 + (door_index - first_door()); }
  // Room-graph neighbours of a label, ascending (empty for 0).
  const std::vector<int>& room_neighbors(int label) const { return room_adj_[label]; }
  bool room_adjacent(int l1, int l2) const { return adj_[l1 * num_labels() + l2] != 0; }
  bool share_neighbor(int l1, int l2) const { return share_[l1 * num_labels() + l2] != 0; }
  // BFS distance over non-wall cells (doors passable), kNoPath if disconnected.
  static constexpr uint16_t kNoPath = 0xffff;
  uint16_t dist(int c1, int c2) const { return dist_[static_cast<size_t>(c1) * num_cells() + c2]; }
  // Row c1 of the MST heuristic's edge distances: row[c2] is dist(c1, c2)
  // if the heuristic admits an edge between objects on these cells (their
  // room labels are equal or adjacent, or, when both objects are doors
  // (both_doors), open onto a common room), else kNoPath.
  const uint16_t* edge_row(int c1, bool both_doors) const {
    return (both_doors ? door_edge_.data() : edge_.data()) + static_cast<size_t>(c1) * num_cells();
  }

  // ---- state access (hot path: no allocation once `out` has been sized)
  void read(const uint64_t* s, DkgStateView& out) const;
  DkgStateView read(const pddl::State& s) const {
    DkgStateView v;
    read(s.data(), v);
    return v;
  }
  bool locked(const DkgStateView& v, int door_index) const { return mask_has(v.locked, door_index - first_door()); }

  // ---- key/door analysis (5.5 (b)); targets are object indices
  KeyDoorSets pathsets(int r0, int g) const;
  KeyDoorSets necessary(const DkgStateView& v, int agent, std::span<const int> targets) const;
  KeyDoorSets recursive(const DkgStateView& v, int agent, std::span<const int> targets, int max_iters = 5) const;

 private:
  DkgMapAnalysis() = default;

  std::shared_ptr<const pddl::Task> task_;
  std::vector<pddl::ObjectId> objects_;
  std::vector<int> index_;  // ObjectId -> object index or -1
  std::vector<Kind> kind_;
  int num_agents_ = 0, num_items_ = 0, num_doors_ = 0;
  std::vector<std::vector<int>> unlockers_;  // per door

  int width_ = 0, height_ = 0, num_rooms_ = 0;
  std::vector<int> labels_;
  std::vector<std::vector<int>> room_adj_;
  std::vector<uint8_t> adj_, share_;  // num_labels^2
  std::vector<uint16_t> dist_;        // num_cells^2
  std::vector<uint16_t> edge_, door_edge_;  // num_cells^2, see edge_row()

  // State layout: per object x/y fluents, per (agent, item) `has` atom, per
  // door `locked`, per agent `active`.
  std::vector<pddl::Task::FluentRef> x_, y_;
  std::vector<pddl::Task::AtomRef> has_;  // [item - num_agents][agent]
  std::vector<pddl::Task::AtomRef> locked_, active_;
};

}  // namespace clips::domains::dkg
