#pragma once
// The scene of a pack that draws no picture (scene "text" in pack.json): a
// state shown as places and what is at each, what each agent holds, the other
// facts, and what changed since the previous state. Read from the state's
// atoms alone, for any domain:
//
//   * agents: the pack's principal and assistant;
//   * places: objects that agents and other objects both stand in a binary
//     relation to, (at human rack) and (on plank1 rack) making `rack` a place
//     (judged over every dynamic atom of the task, so an empty place is still
//     one); and the objects of a relation that puts every agent at exactly
//     one object at the start ((at human x) where only agents move);
//   * an agent's holdings: the non-place objects of its true binary atoms,
//     (holding human plank1);
//   * other facts: every other true dynamic atom, except those that name
//     only agents (whose turn it is, frozen agents);
//   * qualities: an object's qualifier values from the pack (big, wooden).
//
// A domain with no such relations (blocks world) shows its facts only.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "domains/pack.hpp"
#include "pddl/task.hpp"

namespace clips::serve {

class TextScene {
 public:
  // The layout is worked out once per grounded problem.
  TextScene(std::shared_ptr<const pddl::Task> task, const domains::Pack& pack);

  // {"kind": "text", "places": [{"name", "qualities", "agents", "objects": [{"name", "qualities"}]}],
  //  "agents": [{"name", "at", "holds": [{"name", "qualities"}]}], "facts": [...],
  //  "changed": {"added": [...], "removed": [...]}, "text": "...", "active": NAME}
  // `previous`: the state before the last action (nullptr at the start).
  nlohmann::json draw(const pddl::State& s, const pddl::State* previous, const std::string& active) const;

  const std::vector<pddl::ObjectId>& places() const { return places_; }

 private:
  enum class Role { Other, Agent, Place };
  std::vector<std::string> true_atoms(const pddl::State& s) const;
  nlohmann::json object_json(pddl::ObjectId o) const;

  std::shared_ptr<const pddl::Task> task_;
  std::vector<Role> role_;                       // per object
  std::vector<pddl::ObjectId> agents_, places_;  // in problem order
  std::vector<std::vector<std::string>> qualities_;  // per object
};

}  // namespace clips::serve
