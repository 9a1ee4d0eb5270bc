#include "domains/vh/vh_value.hpp"

#include <algorithm>
#include <regex>
#include <set>

#include "util/error.hpp"

namespace clips::domains::vh {

namespace {
bool holds(const uint64_t* s, const pddl::Task::AtomRef& a) { return a.bit >= 0 ? pddl::get_bit(s, a.bit) : a.value; }
}  // namespace

VhValueHeuristic::VhValueHeuristic(const pddl::Task& task) : task_(&task) {
  agents_ = task.objects_of_type("agent");
  fixtures_ = task.objects_of_type("fixture");
  if (agents_.empty() || fixtures_.empty()) throw InputError("the VH value function needs agents and fixtures");
  for (int a : agents_) nograb_.push_back(task.atom(*task.domain().find_predicate("nograb"), {a}));
  auto next_to = *task.domain().find_predicate("next-to");
  next_to_.resize(agents_.size());
  for (size_t a = 0; a < agents_.size(); ++a)
    for (int f : fixtures_) next_to_[a].push_back(task.atom(next_to, {agents_[a], f}));
}

void VhValueHeuristic::prepare(const model::Specification& spec, const pddl::State&) {
  if (spec.goal_text() == goal_text_) return;
  goal_text_ = spec.goal_text();
  const pddl::Task& task = *task_;
  std::vector<int> gi, gf;
  auto add = [](std::vector<int>& v, int o) {
    if (std::find(v.begin(), v.end(), o) == v.end()) v.push_back(o);
  };
  auto object = [&](const std::string& n) {
    auto o = task.find_object(n);
    if (!o) throw InputError("unknown object '" + n + "' in goal " + goal_text_);
    return *o;
  };
  static const std::regex atom(R"(\(\s*(placed|holding|next-to)\s+([^\s()]+)\s+([^\s()]+)\s*\))");
  for (std::sregex_iterator it(goal_text_.begin(), goal_text_.end(), atom), end; it != end; ++it) {
    const std::string pred = (*it)[1], a = (*it)[2], b = (*it)[3];
    if (pred == "placed") {
      add(gi, object(a));
      add(gf, object(b));
    } else if (pred == "holding") {
      add(gi, object(b));
    } else {
      add(gf, object(b));
    }
  }
  fixture_in_goal_.assign(fixtures_.size(), false);
  for (size_t f = 0; f < fixtures_.size(); ++f)
    fixture_in_goal_[f] = std::find(gf.begin(), gf.end(), fixtures_[f]) != gf.end();
  auto placed = *task.domain().find_predicate("placed");
  auto holding = *task.domain().find_predicate("holding");
  items_.clear();
  for (int i : gi) {
    GoalItem g;
    for (int f : fixtures_) g.placed.push_back(task.atom(placed, {i, f}));
    for (int a : agents_) g.holding.push_back(task.atom(holding, {a, i}));
    items_.push_back(std::move(g));
  }
}

double VhValueHeuristic::estimate(const uint64_t* s) {
  const size_t na = agents_.size(), nf = fixtures_.size();
  int ncan = 0;
  for (size_t a = 0; a < na; ++a) ncan += holds(s, nograb_[a]) ? 0 : 1;
  double item_cost = 0;
  // relevant[f]: a non-goal fixture holding a goal item; held[a]: agent a holds a goal item.
  std::vector<char> relevant(nf, 0), held(na, 0);
  for (const GoalItem& g : items_) {
    int fixture = -1, agent = -1;
    for (size_t f = 0; f < nf && fixture < 0; ++f)
      if (holds(s, g.placed[f])) fixture = static_cast<int>(f);
    if (fixture < 0)
      for (size_t a = 0; a < na && agent < 0; ++a)
        if (holds(s, g.holding[a])) agent = static_cast<int>(a);
    if (fixture >= 0 && fixture_in_goal_[fixture]) continue;  // already on the table
    if (fixture >= 0) {
      if (ncan == 0) return model::kInf;
      item_cost += 1.0 + static_cast<double>(na) / ncan;  // grab + put, scaled if one agent cannot grab
      relevant[fixture] = 1;
    } else if (agent >= 0) {
      item_cost += 1.0;  // still needs a put
      held[agent] = 1;
    } else {
      return model::kInf;
    }
  }
  double move_cost = 0;
  size_t n_relevant = std::count(relevant.begin(), relevant.end(), 1);
  if (n_relevant > 0) {
    // Fixtures where an agent already stands need no visit.
    for (size_t f = 0; f < nf; ++f)
      if (relevant[f])
        for (size_t a = 0; a < na; ++a)
          if (holds(s, next_to_[a][f])) {
            relevant[f] = 0;
            break;
          }
    move_cost = static_cast<double>(std::count(relevant.begin(), relevant.end(), 1)) +
                static_cast<double>(std::count(fixture_in_goal_.begin(), fixture_in_goal_.end(), true));
  } else {
    for (size_t a = 0; a < na; ++a) {
      if (!held[a]) continue;
      bool at_goal_fixture = false;
      for (size_t f = 0; f < nf; ++f)
        if (fixture_in_goal_[f] && holds(s, next_to_[a][f])) at_goal_fixture = true;
      move_cost += at_goal_fixture ? 0 : 1;
    }
  }
  return item_cost + move_cost;
}

}  // namespace clips::domains::vh

namespace clips::domains::vh {

void VhPlanningHeuristic::prepare(const model::Specification& spec, const pddl::State& root) {
  VhValueHeuristic::prepare(spec, root);
  const pddl::Task& task = *task_;
  std::set<pddl::ObjectId> gi, gf;
  static const std::regex atom(R"(\(\s*(placed|holding|next-to)\s+([^\s()]+)\s+([^\s()]+)\s*\))");
  const std::string& text = spec.goal_text();
  for (std::sregex_iterator it(text.begin(), text.end(), atom), end; it != end; ++it) {
    auto a = task.find_object((*it)[2]);
    auto b = task.find_object((*it)[3]);
    if (!a || !b) continue;
    if ((*it)[1] == "placed") {
      gi.insert(*a);
      gf.insert(*b);
    } else if ((*it)[1] == "holding") {
      gi.insert(*b);
    } else {
      gf.insert(*b);
    }
  }
  auto placed = task.domain().find_predicate("placed");
  std::set<pddl::ObjectId> holds_goal_item = gf;
  for (auto f : task.objects_of_type("fixture"))
    for (auto i : gi)
      if (placed && task.test(root, task.atom(*placed, {i, f}))) holds_goal_item.insert(f);
  auto nograb = [&](pddl::ObjectId agent) {
    auto p = task.domain().find_predicate("nograb");
    return p && task.test(root, task.atom(*p, {agent}));
  };
  keep_.assign(task.num_actions(), 1);
  for (pddl::ActionId a = 0; a < task.num_actions(); ++a) {
    const auto& ga = task.action(a);
    const std::string& name = task.domain().actions[ga.schema].name;
    bool ng = !ga.args.empty() && nograb(ga.args[0]);
    bool k = true;
    if (name == "stack") {
      k = false;
    } else if (name == "move" && ga.args.size() == 3) {
      k = gf.count(ga.args[2]) || (!ng && holds_goal_item.count(ga.args[2]));
    } else if (name == "grab" && ga.args.size() == 3) {
      k = !ng && gi.count(ga.args[1]);
    } else if (name == "put" && ga.args.size() == 3) {
      k = gi.count(ga.args[1]) ? gf.count(ga.args[2]) > 0 : !ng;
    }
    keep_[a] = k;
  }
}

}  // namespace clips::domains::vh
