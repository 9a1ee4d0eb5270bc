#include "domains/vh/vh_world.hpp"

#include <algorithm>

namespace clips::domains::vh {

using pddl::ObjectId;

VhWorld::VhWorld(const pddl::Task& task) : task_(&task) {
  fixtures_ = task.objects_of_type("fixture");
  items_ = task.objects_of_type("item");
  itypes_ = task.objects_of_type("itype");
  auto agents = task.objects_of_type("agent");
  for (ObjectId a : agents) {
    if (task.object_name(a) == "actor") actor_ = a;
    if (task.object_name(a) == "helper") helper_ = a;
  }
  if (actor_ < 0 || helper_ < 0) throw InputError("VirtualHome needs the agents 'actor' and 'helper'");
}

bool VhWorld::atom(const pddl::State& s, const char* pred, std::vector<ObjectId> args) const {
  auto p = task_->domain().find_predicate(pred);
  if (!p) return false;
  return task_->test(s, task_->atom(*p, args));
}

std::string VhWorld::item_type(ObjectId item) const {
  auto p = task_->domain().find_predicate("itemtype");
  for (ObjectId t : itypes_)
    if (task_->atom(*p, {item, t}).value) return task_->object_name(t);
  return "";
}

bool VhWorld::placed(const pddl::State& s, ObjectId i, ObjectId f) const { return atom(s, "placed", {i, f}); }
bool VhWorld::holding(const pddl::State& s, ObjectId a, ObjectId i) const { return atom(s, "holding", {a, i}); }
bool VhWorld::next_to(const pddl::State& s, ObjectId a, ObjectId f) const { return atom(s, "next-to", {a, f}); }
bool VhWorld::stacked(const pddl::State& s, ObjectId t, ObjectId b) const { return atom(s, "stacked", {t, b}); }
bool VhWorld::active(const pddl::State& s, ObjectId a) const { return atom(s, "active", {a}); }

std::vector<ObjectId> VhWorld::items_at(const pddl::State& s, ObjectId f) const {
  std::vector<ObjectId> here;
  for (ObjectId i : items_)
    if (placed(s, i, f)) here.push_back(i);
  // Order piles top first: an item's depth is the number of items above it.
  auto depth = [&](ObjectId i) {
    int d = 0;
    for (ObjectId cur = i;;) {
      ObjectId above = -1;
      for (ObjectId j : here)
        if (stacked(s, j, cur)) above = j;
      if (above < 0 || d > static_cast<int>(here.size())) return d;
      ++d;
      cur = above;
    }
  };
  std::stable_sort(here.begin(), here.end(), [&](ObjectId a, ObjectId b) { return depth(a) < depth(b); });
  return here;
}

std::string VhWorld::describe(const pddl::State& s) const {
  std::string out = "active: " + name(active(s, actor_) ? actor_ : helper_) + "\n";
  for (ObjectId a : {actor_, helper_}) {
    out += name(a) + " at";
    for (ObjectId f : fixtures_)
      if (next_to(s, a, f)) out += " " + name(f);
    out += ", holds:";
    bool any = false;
    for (ObjectId i : items_)
      if (holding(s, a, i)) out += " " + name(i), any = true;
    out += any ? "\n" : " nothing\n";
  }
  for (ObjectId f : fixtures_) {
    out += name(f) + ":";
    auto here = items_at(s, f);
    if (here.empty()) out += " (empty)";
    for (ObjectId i : here) out += " " + name(i);
    out += "\n";
  }
  return out;
}

}  // namespace clips::domains::vh
