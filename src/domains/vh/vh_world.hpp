#pragma once
// Read-only view of a VirtualHome task: fixtures, items (with their item
// type), piles, and where the two agents are and what they hold.
#include <string>
#include <vector>

#include "pddl/task.hpp"

namespace clips::domains::vh {

class VhWorld {
 public:
  explicit VhWorld(const pddl::Task& task);

  const pddl::Task& task() const { return *task_; }
  pddl::ObjectId actor() const { return actor_; }
  pddl::ObjectId helper() const { return helper_; }
  const std::vector<pddl::ObjectId>& fixtures() const { return fixtures_; }
  const std::vector<pddl::ObjectId>& items() const { return items_; }
  const std::string& name(pddl::ObjectId o) const { return task_->object_name(o); }
  std::string item_type(pddl::ObjectId item) const;

  bool placed(const pddl::State& s, pddl::ObjectId item, pddl::ObjectId fixture) const;
  bool holding(const pddl::State& s, pddl::ObjectId agent, pddl::ObjectId item) const;
  bool next_to(const pddl::State& s, pddl::ObjectId agent, pddl::ObjectId fixture) const;
  bool stacked(const pddl::State& s, pddl::ObjectId top, pddl::ObjectId below) const;
  bool active(const pddl::State& s, pddl::ObjectId agent) const;
  // Items at a fixture, top of each pile first.
  std::vector<pddl::ObjectId> items_at(const pddl::State& s, pddl::ObjectId fixture) const;
  std::string describe(const pddl::State& s) const;

 private:
  bool atom(const pddl::State& s, const char* pred, std::vector<pddl::ObjectId> args) const;
  const pddl::Task* task_;
  pddl::ObjectId actor_ = -1, helper_ = -1;
  std::vector<pddl::ObjectId> fixtures_, items_, itypes_;
};

}  // namespace clips::domains::vh
