#include "serve/text_scene.hpp"

#include <algorithm>
#include <functional>

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
  // Where agents stand: what an agent is related to by a predicate that, at
  // the start, relates every agent to exactly one object ((at human x)).
  // What else an agent relates to (a bag it can hold) is no place.
  std::vector<char> stands(role_.size(), 0);
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
          stands[t.atom_info(bit).second[1]] = 1;
    }
  }
  // Without such a predicate, a place is the second argument of a binary
  // atom whose first argument is an agent, and of one whose first is not.
  if (std::find(stands.begin(), stands.end(), 1) == stands.end()) {
    std::vector<char> by_agent(role_.size(), 0), by_other(role_.size(), 0);
    for (int bit = 0; bit < t.num_atoms(); ++bit) {
      const auto& [pred, args] = t.atom_info(bit);
      if (args.size() != 2 || role_[args[1]] == Role::Agent) continue;
      (role_[args[0]] == Role::Agent ? by_agent : by_other)[args[1]] = 1;
    }
    for (size_t o = 0; o < role_.size(); ++o) stands[o] = by_agent[o] && by_other[o];
  }
  for (ObjectId o = 0; o < t.num_objects(); ++o)
    if (role_[o] == Role::Other && stands[o]) {
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
  // Things that hold others (a chest, a shelf): the second argument of a
  // changing binary atom between two things. One that stands at a place by
  // a fact no action changes, (stands chest study), is drawn there.
  std::vector<char> holder(role_.size(), 0);
  std::set<pddl::PredId> containing;  // predicates of such atoms, (inside ?i ?c)
  for (int bit = 0; bit < t.num_atoms(); ++bit) {
    const auto& [pred, args] = t.atom_info(bit);
    if (args.size() == 2 && role_[args[0]] == Role::Other && role_[args[1]] == Role::Other && args[0] != args[1]) {
      holder[args[1]] = 1;
      containing.insert(pred);
    }
  }
  // The same predicate as a fact no action changes means the same: a lamp
  // that stays inside the basket it is in is drawn in it.
  for (pddl::PredId p : containing)
    for (ObjectId a = 0; a < t.num_objects(); ++a)
      for (ObjectId b = 0; b < t.num_objects(); ++b)
        if (a != b && role_[a] == Role::Other && role_[b] == Role::Other)
          if (const auto ref = t.atom(p, {a, b}); ref.bit < 0 && ref.value) {
            static_contents_.push_back({p, a, b});
            holder[b] = 1;
          }
  const auto& preds = t.domain().predicates;
  for (ObjectId x = 0; x < t.num_objects(); ++x) {
    if (!holder[x]) continue;
    for (pddl::PredId p = 0; p < static_cast<pddl::PredId>(preds.size()) && !sited_.count(x); ++p) {
      if (preds[static_cast<size_t>(p)].arg_types.size() != 2) continue;
      for (ObjectId place : places_)
        if (const auto ref = t.atom(p, {x, place}); ref.bit < 0 && ref.value) {
          sited_[x] = place;
          break;
        }
    }
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
  const size_t n = role_.size();
  std::map<ObjectId, std::vector<ObjectId>> at_place, agents_at;  // place -> things / agents
  std::map<ObjectId, std::vector<ObjectId>> holds;               // agent -> things
  std::map<ObjectId, std::vector<ObjectId>> where;               // agent -> places
  // Thing -> (relation, thing in or on it), and whether a thing is anywhere
  // the scene shows (at a place, held, or in another thing).
  std::map<ObjectId, std::vector<std::pair<std::string, ObjectId>>> contents;
  std::vector<char> placed(n, 0);
  std::map<ObjectId, std::vector<std::string>> states;  // thing or place -> its one-argument atoms
  std::vector<int> leftover;                              // atoms for `facts`, unless a state shows them
  std::vector<std::pair<ObjectId, int>> unary;            // (object, atom) of one-argument atoms
  for (int bit = 0; bit < t.num_atoms(); ++bit) {
    if (!pddl::get_bit(s.data(), bit)) continue;
    const auto& [pred, args] = t.atom_info(bit);
    if (!args.empty() && std::all_of(args.begin(), args.end(), [&](ObjectId o) { return role_[o] == Role::Agent; }))
      continue;
    if (args.size() == 2 && role_[args[1]] == Role::Place && role_[args[0]] != Role::Place) {
      if (role_[args[0]] == Role::Agent) {
        where[args[0]].push_back(args[1]);
        agents_at[args[1]].push_back(args[0]);
      } else {
        at_place[args[1]].push_back(args[0]);
        placed[args[0]] = 1;
      }
      continue;
    }
    if (args.size() == 2 && role_[args[0]] == Role::Agent && role_[args[1]] == Role::Other) {
      holds[args[0]].push_back(args[1]);
      placed[args[1]] = 1;
      continue;
    }
    if (args.size() == 2 && role_[args[0]] == Role::Other && role_[args[1]] == Role::Other && args[0] != args[1]) {
      contents[args[1]].push_back({t.domain().predicates[static_cast<size_t>(pred)].name, args[0]});
      placed[args[0]] = 1;
      continue;
    }
    if (args.size() == 1) unary.push_back({args[0], bit});
    leftover.push_back(bit);
  }
  for (const auto& [pred, thing, in] : static_contents_) {
    contents[in].push_back({t.domain().predicates[static_cast<size_t>(pred)].name, thing});
    placed[thing] = 1;
  }
  // A thing placed by a static fact, while no atom says where it is now.
  for (const auto& [thing, place] : sited_)
    if (!placed[thing]) {
      at_place[place].push_back(thing);
      placed[thing] = 1;
    }
  for (auto* m : {&at_place, &agents_at, &holds, &where})
    for (auto& [k, v] : *m) std::sort(v.begin(), v.end());
  // Things that hold something and are nowhere else: drawn on their own.
  std::vector<ObjectId> others;
  for (const auto& [thing, in] : contents)
    if (!placed[thing] && role_[thing] == Role::Other) others.push_back(thing);

  // What is drawn gets its states beside it; the rest of the atoms are facts.
  std::vector<char> drawn(n, 0);
  for (ObjectId p : places_) drawn[p] = 1;
  for (size_t o = 0; o < n; ++o) drawn[o] |= placed[o];
  for (ObjectId o : others) drawn[o] = 1;
  std::set<int> shown;
  for (const auto& [o, bit] : unary)
    if (drawn[o] && role_[o] != Role::Agent) {
      states[o].push_back(t.domain().predicates[static_cast<size_t>(t.atom_info(bit).first)].name);
      shown.insert(bit);
    }
  json facts = json::array();
  for (int bit : leftover)
    if (!shown.count(bit)) facts.push_back(t.atom_str(bit));

  auto names = [&](const std::vector<ObjectId>& os) {
    json a = json::array();
    for (ObjectId o : os) a.push_back(t.object_name(o));
    return a;
  };
  // A thing with its states and what is in or on it, as JSON and as text;
  // `depth` stops a cycle of relations ((on a b) and (on b a)).
  std::function<json(ObjectId, int)> thing_json = [&](ObjectId o, int depth) {
    json j = object_json(o);
    if (const auto it = states.find(o); it != states.end()) j["states"] = it->second;
    if (const auto it = contents.find(o); it != contents.end() && depth < 8) {
      json in = json::array();
      for (const auto& [rel, x] : it->second) {
        json xj = thing_json(x, depth + 1);
        xj["relation"] = rel;
        in.push_back(std::move(xj));
      }
      j["contents"] = std::move(in);
    }
    return j;
  };
  std::function<std::string(ObjectId, int)> described = [&](ObjectId o, int depth) {
    std::string d = t.object_name(o);
    std::vector<std::string> words = qualities_[o];
    if (const auto it = states.find(o); it != states.end()) words.insert(words.end(), it->second.begin(), it->second.end());
    if (!words.empty()) {
      d += " (";
      for (size_t i = 0; i < words.size(); ++i) d += (i ? ", " : "") + words[i];
      d += ")";
    }
    if (const auto it = contents.find(o); it != contents.end() && depth < 8) {
      d += " [";
      std::string last;
      for (size_t i = 0; i < it->second.size(); ++i) {
        const auto& [rel, x] = it->second[i];
        d += (i ? ", " : "") + (rel != last ? rel + ": " : std::string()) + described(x, depth + 1);
        last = rel;
      }
      d += "]";
    }
    return d;
  };
  std::string text;
  json places = json::array();
  for (ObjectId p : places_) {
    json objs = json::array();
    std::string line = t.object_name(p);
    if (const auto it = states.find(p); it != states.end())
      for (size_t i = 0; i < it->second.size(); ++i) line += (i ? ", " : " (") + it->second[i] + (i + 1 == it->second.size() ? ")" : "");
    line += ":";
    for (ObjectId o : at_place[p]) {
      objs.push_back(thing_json(o, 0));
      line += " " + described(o, 0);
    }
    for (ObjectId a : agents_at[p]) line += " [" + t.object_name(a) + "]";
    text += line + "\n";
    json pj = object_json(p);
    if (const auto it = states.find(p); it != states.end()) pj["states"] = it->second;
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
      held.push_back(thing_json(holds[a][i], 0));
      line += (i ? ", " : w.empty() ? " holding " : ", holding ") + described(holds[a][i], 0);
    }
    if (t.object_name(a) == active) line += " (to move)";
    text += line + "\n";
    agents.push_back({{"name", t.object_name(a)},
                      {"at", w.empty() ? json(nullptr) : json(t.object_name(w.front()))},
                      {"holds", std::move(held)}});
  }
  json loose = json::array();
  for (ObjectId o : others) {
    loose.push_back(thing_json(o, 0));
    text += described(o, 0) + "\n";
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
  return {{"kind", "text"}, {"places", std::move(places)}, {"agents", std::move(agents)}, {"others", std::move(loose)},
          {"facts", std::move(facts)}, {"changed", std::move(changed)}, {"text", text}, {"active", active}};
}

}  // namespace clips::serve
