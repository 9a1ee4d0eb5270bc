#include "serve/text_scene.hpp"

#include <algorithm>

#include "pddl/state.hpp"

namespace clips::serve {

using nlohmann::json;
using pddl::ObjectId;

TextScene::TextScene(std::shared_ptr<const pddl::Task> task, const domains::Pack& pack) : task_(std::move(task)) {
  const pddl::Task& t = *task_;
  role_.assign(static_cast<size_t>(t.num_objects()), Role::Other);
  for (const std::string& name : {pack.roles().principal, pack.roles().assistant})
    if (auto o = t.find_object(name); o && role_[*o] != Role::Agent) {
      role_[*o] = Role::Agent;
      agents_.push_back(*o);
    }
  std::sort(agents_.begin(), agents_.end());
  // A place: the second argument of a binary atom whose first argument is an
  // agent, and of one whose first argument is not.
  std::vector<char> by_agent(role_.size(), 0), by_other(role_.size(), 0);
  for (int bit = 0; bit < t.num_atoms(); ++bit) {
    const auto& [pred, args] = t.atom_info(bit);
    if (args.size() != 2 || role_[args[1]] == Role::Agent) continue;
    (role_[args[0]] == Role::Agent ? by_agent : by_other)[args[1]] = 1;
  }
  // Also a place: what an agent is related to by a predicate that, at the
  // start, relates every agent to exactly one object ((at human x) where
  // nothing but agents is anywhere).
  {
    const pddl::State init = t.initial_state();
    std::map<pddl::PredId, std::map<ObjectId, int>> count;  // predicate -> agent -> true atoms at the start
    for (int bit = 0; bit < t.num_atoms(); ++bit) {
      const auto& [pred, args] = t.atom_info(bit);
      if (args.size() != 2 || role_[args[0]] != Role::Agent || role_[args[1]] == Role::Agent) continue;
      count[pred][args[0]] += pddl::get_bit(init.data(), bit) ? 1 : 0;
    }
    for (const auto& [pred, per_agent] : count) {
      bool locates = per_agent.size() == agents_.size();
      for (const auto& [agent, n] : per_agent) locates &= n == 1;
      if (!locates) continue;
      for (int bit = 0; bit < t.num_atoms(); ++bit)
        if (t.atom_info(bit).first == pred && role_[t.atom_info(bit).second[0]] == Role::Agent)
          by_other[t.atom_info(bit).second[1]] = by_agent[t.atom_info(bit).second[1]] = 1;
    }
  }
  for (ObjectId o = 0; o < t.num_objects(); ++o)
    if (role_[o] == Role::Other && by_agent[o] && by_other[o]) {
      role_[o] = Role::Place;
      places_.push_back(o);
    }
  qualities_.resize(role_.size());
  const auto qualifier = pack.qualifier_of(t);
  for (ObjectId o = 0; o < t.num_objects(); ++o) {
    const std::string& name = t.object_name(o);
    for (const auto& q : qualifier(name))
      if (q.args.size() == 2) qualities_[o].push_back(q.args[0] == name ? q.args[1] : q.args[0]);
  }
}

std::vector<std::string> TextScene::true_atoms(const pddl::State& s) const {
  std::vector<std::string> out;
  for (int bit = 0; bit < task_->num_atoms(); ++bit) {
    if (!pddl::get_bit(s.data(), bit)) continue;
    const auto& args = task_->atom_info(bit).second;
    // Atoms of agents only say whose turn it is (active, frozen): the scene has `active`.
    if (!args.empty() && std::all_of(args.begin(), args.end(), [&](ObjectId o) { return role_[o] == Role::Agent; }))
      continue;
    out.push_back(task_->atom_str(bit));
  }
  return out;
}

json TextScene::object_json(ObjectId o) const {
  return {{"name", task_->object_name(o)}, {"qualities", qualities_[o]}};
}

json TextScene::draw(const pddl::State& s, const pddl::State* previous, const std::string& active) const {
  const pddl::Task& t = *task_;
  std::map<ObjectId, std::vector<ObjectId>> at_place, agents_at;  // place -> objects / agents
  std::map<ObjectId, std::vector<ObjectId>> holds;               // agent -> objects
  std::map<ObjectId, std::vector<ObjectId>> where;               // agent -> places
  json facts = json::array();
  for (int bit = 0; bit < t.num_atoms(); ++bit) {
    if (!pddl::get_bit(s.data(), bit)) continue;
    const auto& args = t.atom_info(bit).second;
    if (!args.empty() && std::all_of(args.begin(), args.end(), [&](ObjectId o) { return role_[o] == Role::Agent; }))
      continue;
    if (args.size() == 2 && role_[args[1]] == Role::Place) {
      if (role_[args[0]] == Role::Agent) {
        where[args[0]].push_back(args[1]);
        agents_at[args[1]].push_back(args[0]);
      } else {
        at_place[args[1]].push_back(args[0]);
      }
      continue;
    }
    if (args.size() == 2 && role_[args[0]] == Role::Agent && role_[args[1]] == Role::Other) {
      holds[args[0]].push_back(args[1]);
      continue;
    }
    facts.push_back(t.atom_str(bit));
  }
  for (auto* m : {&at_place, &agents_at, &holds, &where})
    for (auto& [k, v] : *m) std::sort(v.begin(), v.end());
  auto names = [&](const std::vector<ObjectId>& os) {
    json a = json::array();
    for (ObjectId o : os) a.push_back(t.object_name(o));
    return a;
  };
  auto described = [&](ObjectId o) {
    std::string d = t.object_name(o);
    if (!qualities_[o].empty()) {
      d += " (";
      for (size_t i = 0; i < qualities_[o].size(); ++i) d += (i ? ", " : "") + qualities_[o][i];
      d += ")";
    }
    return d;
  };
  std::string text;
  json places = json::array();
  for (ObjectId p : places_) {
    json objs = json::array();
    std::string line = t.object_name(p) + ":";
    for (ObjectId o : at_place[p]) {
      objs.push_back(object_json(o));
      line += " " + described(o);
    }
    for (ObjectId a : agents_at[p]) line += " [" + t.object_name(a) + "]";
    text += line + "\n";
    json pj = object_json(p);
    pj["agents"] = names(agents_at[p]);
    pj["objects"] = std::move(objs);
    places.push_back(std::move(pj));
  }
  json agents = json::array();
  for (ObjectId a : agents_) {
    json held = json::array();
    std::string line = t.object_name(a);
    const auto& w = where[a];
    if (!w.empty()) line += " at " + t.object_name(w.front());
    for (size_t i = 1; i < w.size(); ++i) line += ", " + t.object_name(w[i]);
    for (size_t i = 0; i < holds[a].size(); ++i) {
      held.push_back(object_json(holds[a][i]));
      line += (i ? ", " : w.empty() ? " holding " : ", holding ") + described(holds[a][i]);
    }
    if (t.object_name(a) == active) line += " (to move)";
    text += line + "\n";
    agents.push_back({{"name", t.object_name(a)},
                      {"at", w.empty() ? json(nullptr) : json(t.object_name(w.front()))},
                      {"holds", std::move(held)}});
  }
  for (const auto& f : facts) text += f.get<std::string>() + "\n";
  json changed = {{"added", json::array()}, {"removed", json::array()}};
  if (previous) {
    const auto now = true_atoms(s), before = true_atoms(*previous);
    const std::set<std::string> now_set(now.begin(), now.end()), before_set(before.begin(), before.end());
    for (const auto& a : now)
      if (!before_set.count(a)) changed["added"].push_back(a);
    for (const auto& a : before)
      if (!now_set.count(a)) changed["removed"].push_back(a);
  }
  return {{"kind", "text"}, {"places", std::move(places)}, {"agents", std::move(agents)},
          {"facts", std::move(facts)}, {"changed", std::move(changed)}, {"text", text}, {"active", active}};
}

}  // namespace clips::serve
