#pragma once
// Read-only view of a Doors-Keys-Gems task: the wall grid, the agents, keys,
// doors and gems, their colours, and accessors for where things are in a
// State. Everything domain-specific that the heuristic, the language layer and
// the pictures need to know about mDKG geometry comes from here.
#include <optional>
#include <string>
#include <vector>

#include "pddl/task.hpp"

namespace clips::domains::dkg {

struct Cell {
  int x = -1, y = -1;  // 1-based; (-1, -1) when off the grid
  bool on_grid() const { return x >= 1 && y >= 1; }
  bool operator==(const Cell& o) const { return x == o.x && y == o.y; }
};

class DkgWorld {
 public:
  explicit DkgWorld(const pddl::Task& task);

  const pddl::Task& task() const { return *task_; }
  int width() const { return width_; }
  int height() const { return height_; }
  bool wall(int x, int y) const;  // 1-based; outside the grid counts as wall

  pddl::ObjectId human() const { return human_; }
  pddl::ObjectId robot() const { return robot_; }
  const std::vector<pddl::ObjectId>& agents() const { return agents_; }  // human, robot
  const std::vector<pddl::ObjectId>& keys() const { return keys_; }
  const std::vector<pddl::ObjectId>& doors() const { return doors_; }
  const std::vector<pddl::ObjectId>& gems() const { return gems_; }
  const std::string& name(pddl::ObjectId o) const { return task_->object_name(o); }
  std::string color(pddl::ObjectId o) const;  // "" if none

  Cell pos(const pddl::State& s, pddl::ObjectId o) const;
  // The agent holding item `i`, if any.
  std::optional<pddl::ObjectId> holder(const pddl::State& s, pddl::ObjectId i) const;
  bool has(const pddl::State& s, pddl::ObjectId agent, pddl::ObjectId item) const;
  bool locked(const pddl::State& s, pddl::ObjectId door) const;
  bool active(const pddl::State& s, pddl::ObjectId agent) const;
  pddl::ObjectId active_agent(const pddl::State& s) const;
  bool picked_up_by(const pddl::State& s, pddl::ObjectId agent, pddl::ObjectId item) const;
  bool unlocked_by(const pddl::State& s, pddl::ObjectId agent, pddl::ObjectId door) const;

  // ASCII picture: W wall, . floor, r/y/b/e/p keys, R/Y/B/E/P locked doors,
  // _ unlocked door, g gem, h human, m robot, @ both agents.
  std::string ascii(const pddl::State& s) const;
  // Inventory, active agent and door states, one line each.
  std::string describe(const pddl::State& s) const;

 private:
  const pddl::Task* task_;
  const pddl::BitMatrix* walls_ = nullptr;
  int width_ = 0, height_ = 0;
  pddl::ObjectId human_ = -1, robot_ = -1;
  std::vector<pddl::ObjectId> agents_, keys_, doors_, gems_;
  std::vector<pddl::Task::FluentRef> x_, y_;       // per object
  std::vector<std::string> color_;                  // per object
};

}  // namespace clips::domains::dkg
