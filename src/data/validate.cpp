#include "data/validate.hpp"

#include <algorithm>
#include <set>

#include "pddl/parser.hpp"

namespace clips::data {

std::vector<std::string> true_options(const Dataset& ds, const PlanRecord& p) {
  std::vector<std::string> out;
  auto add = [&](const std::string& o) {
    if (std::find(out.begin(), out.end(), o) == out.end()) out.push_back(o);
  };
  for (auto& line : p.completed.actions) {
    auto e = pddl::read_one_sexpr(line.text, line.loc.file);
    if (!e.is_list || e.items.size() < 2) continue;
    const std::string& h = e.head();
    if (ds.kind() == DomainKind::DoorsKeysGems) {
      if (e.items[1].atom != "robot") continue;
      if (p.tag == "keys" && h == "pickup" && e.items.size() == 3) add(e.items[2].atom);
      if (p.tag == "doors" && h == "unlock" && e.items.size() == 4) add(e.items[3].atom);
    } else if (ds.kind() == DomainKind::VirtualHome) {
      if (h == "grab" && e.items[1].atom == "helper" && e.items.size() >= 3) add(e.items[2].atom);
    }
  }
  return out;
}

namespace {
int trailing_number(const std::string& s) {
  size_t i = s.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1]))) --i;
  return i < s.size() ? std::stoi(s.substr(i)) : -1;
}
}  // namespace

PlanCheck validate_plan(const Dataset& ds, const PlanRecord& p) {
  PlanCheck r;
  r.plan_id = p.id;
  try {
    auto task = ds.task(p.problem_id);
    auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
    auto comp = pddl::simulate(*task, obs.states.back(), p.completed);
    r.observed_steps = static_cast<int>(obs.actions.size());
    r.completed_steps = static_cast<int>(comp.actions.size());
    auto goals = ds.candidate_goals(p);
    int truth = ds.true_goal_index(p);
    std::vector<int> reached;
    for (size_t i = 0; i < goals.size(); ++i) {
      pddl::CompiledCondition g = task->compile_text(goals[i].condition,
                                              goals[i].source.empty() ? "goal " + goals[i].label : goals[i].source);
      if (g.holds(comp.states.back())) reached.push_back(static_cast<int>(i));
    }
    if (ds.kind() == DomainKind::VirtualHome) {
      // VH goals nest (juice1 is part of juice2): the completion must reach the
      // true goal, and every other goal it reaches must be a part of it.
      auto atoms_of = [&](const std::string& text) {
        auto e = pddl::read_one_sexpr(text, "goal");
        std::set<std::string> out;
        if (e.head() == "and")
          for (size_t i = 1; i < e.items.size(); ++i) out.insert(e.items[i].str());
        else
          out.insert(e.str());
        return out;
      };
      auto truth_atoms = atoms_of(goals[truth].condition);
      std::vector<int> maximal;
      for (int i : reached) {
        auto a = atoms_of(goals[i].condition);
        bool part = i != truth && std::includes(truth_atoms.begin(), truth_atoms.end(), a.begin(), a.end());
        if (!part) maximal.push_back(i);
      }
      reached = maximal;
    }
    if (reached.size() != 1) {
      std::string names;
      for (int i : reached) names += " " + goals[i].label;
      r.error = "completion reaches " + std::to_string(reached.size()) + " candidate goals (expected exactly 1):" + names;
      return r;
    }
    if (reached[0] != truth) {
      r.error = "completion reaches " + goals[reached[0]].label + " but the dataset's true goal is " + goals[truth].label;
      return r;
    }
    r.goal = goals[truth].label;
    if (ds.kind() == DomainKind::DoorsKeysGems) {
      if (p.observed.utterances.size() != 1) {
        r.error = "expected exactly one utterance in the observed plan, found " + std::to_string(p.observed.utterances.size());
        return r;
      }
      if (p.pragmatic_utterance && *p.pragmatic_utterance != p.observed.utterances[0].text) {
        r.error = "utterances/pragmatic/" + p.id + ".txt differs from the observed plan's utterance";
        return r;
      }
      if (auto st = ds.stimulus(p.id)) {
        if (st->timesteps != r.observed_steps) {
          r.error = "stimuli.json says timesteps " + std::to_string(st->timesteps) + ", plan has " + std::to_string(r.observed_steps);
          return r;
        }
        if (st->goal != truth) {
          r.error = "stimuli.json goal index " + std::to_string(st->goal) + " differs from the completion's goal " + std::to_string(truth);
          return r;
        }
        std::vector<int> nums;
        for (auto& o : true_options(ds, p)) nums.push_back(trailing_number(o));
        std::sort(nums.begin(), nums.end());
        if (nums != st->best_options) {
          r.error = "stimuli.json best_option differs from the robot's actions in the completion";
          return r;
        }
      }
    }
    r.ok = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

ValidationReport validate_dataset(const Dataset& ds) {
  ValidationReport rep;
  for (auto& p : ds.plans()) {
    rep.results.push_back(validate_plan(ds, p));
    if (!rep.results.back().ok) ++rep.failed;
  }
  // Plans whose files did not load are failures too, each with its file's error.
  for (auto& b : ds.broken_plans()) {
    PlanCheck c;
    c.plan_id = b.id;
    c.error = b.error;
    rep.results.push_back(std::move(c));
    ++rep.failed;
  }
  return rep;
}

}  // namespace clips::data
