#pragma once
// Minimal dataset reader for the listener tests. test_language links only
// clips_language (not clips_data), so the plans are read with the pddl layer
// directly: the problem of a plan is the first dot-separated part of its id
// and the literal utterance is the first line of utterances/literal/<id>.txt.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "test_paths.hpp"

namespace clips::language::testing {

struct PlanData {
  std::string id, problem_id;
  std::shared_ptr<const pddl::Task> task;
  pddl::PlanFile observed, completed;
  std::string literal_utterance;  // "" when the plan has no file (demo plans)
  pddl::State s_T;                // end of the observed plan: where the utterance is heard
};

inline std::string first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

class DatasetFixture {
 public:
  explicit DatasetFixture(const std::string& dir) : dir_(dir) {
    domain_ = std::make_shared<pddl::Domain>(pddl::load_domain(dir + "/domain.pddl"));
    std::vector<std::string> ids;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/plans/observed"))
      if (e.path().extension() == ".pddl") ids.push_back(e.path().stem().string());
    std::sort(ids.begin(), ids.end());
    for (const auto& id : ids) {
      PlanData p;
      p.id = id;
      p.problem_id = id.substr(0, id.find('.'));
      p.task = task(p.problem_id);
      p.observed = pddl::load_plan(dir + "/plans/observed/" + id + ".pddl");
      p.completed = pddl::load_plan(dir + "/plans/completed/" + id + ".pddl");
      const std::filesystem::path lit = dir + "/utterances/literal/" + id + ".txt";
      if (std::filesystem::exists(lit)) p.literal_utterance = first_line(lit);
      p.s_T = pddl::simulate(*p.task, p.task->initial_state(), p.observed).states.back();
      plans_.push_back(std::move(p));
    }
  }

  std::shared_ptr<const pddl::Task> task(const std::string& problem_id) {
    auto& t = tasks_[problem_id];
    if (!t) {
      auto prob = std::make_shared<pddl::Problem>(
          pddl::load_problem(*domain_, dir_ + "/problems/" + problem_id + ".pddl", /*with_goal=*/false));
      pddl::GroundingOptions opts;
      opts.keep_dynamic = {"frozen", "nograb", "noput"};
      t = std::make_shared<pddl::Task>(domain_, prob, opts);
    }
    return t;
  }

  const std::vector<PlanData>& plans() const { return plans_; }
  const PlanData& plan(const std::string& id) const {
    for (const auto& p : plans_)
      if (p.id == id) return p;
    throw std::runtime_error("no plan " + id);
  }

 private:
  std::string dir_;
  std::shared_ptr<pddl::Domain> domain_;
  std::map<std::string, std::shared_ptr<const pddl::Task>> tasks_;
  std::vector<PlanData> plans_;
};

inline bool have_vh_dataset() { return std::filesystem::exists(paths::vh_dataset() + "/domain.pddl"); }

}  // namespace clips::language::testing
