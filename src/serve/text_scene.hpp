#pragma once
// The scene of a pack that draws no picture (scene "text" in pack.json): a
// state shown as places and what is at each, what each agent holds, the other
// facts, and what changed since the previous state. Read from the state's
// atoms alone, for any domain:
//
//   * agents: the pack's principal and assistant;
//   * places: where agents stand: the objects of a relation that puts every
//     agent at exactly one object at the start ((at human rack)). A domain
//     without one: objects that agents and other objects both stand in a
//     binary relation to, (at human rack) and (on plank1 rack) making `rack`
//     a place (judged over every dynamic atom of the task, so an empty place
//     is still one);
//   * an agent's holdings: the non-place objects of its true binary atoms,
//     (holding human plank1);
//   * what is in or on a thing: a true binary atom relating two objects that
//     are neither agents nor places, (in key1 chest): the key is shown in the
//     chest, wherever the chest is (at a place, carried, or on its own when
//     nothing says where); so is a fact no action changes of the same
//     predicate (a lamp that stays in its basket). A thing that holds others
//     and sits at a place by a fact no action changes, (stands chest study),
//     is shown at that place;
//   * states: an object's true one-argument atoms, (open chest), beside it;
//   * other facts: every other true dynamic atom, except those that name
//     only agents (whose turn it is, frozen agents);
//   * qualities: an object's qualifier values from the pack (big, wooden).
//
// A domain with no such relations (blocks world without agents) shows its
// facts only.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "domains/pack.hpp"
#include "pddl/task.hpp"

namespace clips::serve {

class TextScene {
 public:
  // The layout is worked out once per grounded problem.
  TextScene(std::shared_ptr<const pddl::Task> task, const domains::Pack& pack);

  // {"kind": "text", "places": [{"name", "qualities", "agents", "objects": [THING], "states"?}],
  //  "agents": [{"name", "at", "holds": [THING]}], "others": [THING], "facts": [...],
  //  "changed": {"added": [...], "removed": [...]}, "text": "...", "active": NAME}
  // THING: {"name", "qualities", "states"?: [...], "contents"?: [THING with "relation"]};
  // `others`: things that hold something and are nowhere the scene shows.
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
  // Where a thing that holds others stands by a static fact, (stands chest
  // study): chest -> study; used while no true atom says where it is.
  std::map<pddl::ObjectId, pddl::ObjectId> sited_;
  // Static facts of a predicate that relates things that hold others,
  // (inside lamp1 basket1) where no action moves the lamp: (predicate, thing, holder).
  std::vector<std::tuple<pddl::PredId, pddl::ObjectId, pddl::ObjectId>> static_contents_;
};

}  // namespace clips::serve
