// The hand-written workshop dataset (data/datasets/workshop): its goal sets
// are well formed, every observed plan and its completion are applicable with
// turns alternating human/robot, and every completion reaches its plan's true
// goal (the label in the plan's file name) and no other candidate goal of the
// problem that is not a part of the true one. The loader does not read goal
// sets for this domain yet, so the test reads them itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "data/dataset.hpp"
#include "util/error.hpp"
#include "pddl/plan.hpp"
#include "pddl/sexpr.hpp"
#include "test_paths.hpp"

namespace clips::data {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(paths::source_dir()) / "data" / "datasets" / "workshop";

std::vector<std::string> nonblank_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    line.erase(0, line.find_first_not_of(" \t\r"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The top-level conjuncts of a goal condition, printed.
std::set<std::string> conjuncts(const std::string& condition) {
  auto e = pddl::read_one_sexpr(condition, "goal");
  std::set<std::string> out;
  if (e.head() == "and")
    for (size_t i = 1; i < e.items.size(); ++i) out.insert(e.items[i].str());
  else
    out.insert(e.str());
  return out;
}

class WorkshopDataset : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = Dataset::load(kDir.string());
    for (auto& e : fs::directory_iterator(kDir / "goals" / "definitions"))
      definitions_[e.path().stem().string()] = read_text(e.path());
    for (auto& e : fs::directory_iterator(kDir / "goals" / "sets"))
      goal_sets_[e.path().stem().string()] = nonblank_lines(e.path());
  }
  static const Dataset& ds() { return *dataset_; }

  static std::optional<Dataset> dataset_;
  static std::map<std::string, std::string> definitions_;             // label -> condition
  static std::map<std::string, std::vector<std::string>> goal_sets_;  // problem -> labels
};

std::optional<Dataset> WorkshopDataset::dataset_;
std::map<std::string, std::string> WorkshopDataset::definitions_;
std::map<std::string, std::vector<std::string>> WorkshopDataset::goal_sets_;

// The agent of a ground action: its first argument.
std::string agent_of(const pddl::Task& task, pddl::ActionId a) { return task.object_name(task.action(a).args.at(0)); }

TEST_F(WorkshopDataset, EveryProblemHasAGoalSetOfThreeToSixDefinedGoalsThatCompile) {
  std::set<std::string> problems;
  for (auto& e : fs::directory_iterator(kDir / "problems")) problems.insert(e.path().stem().string());
  EXPECT_GE(problems.size(), 8u);
  std::set<std::string> with_sets;
  for (auto& [p, labels] : goal_sets_) with_sets.insert(p);
  EXPECT_EQ(with_sets, problems);
  for (auto& [problem, labels] : goal_sets_) {
    SCOPED_TRACE("goals/sets/" + problem + ".txt");
    EXPECT_GE(labels.size(), 3u);
    EXPECT_LE(labels.size(), 6u);
    EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), labels.size()) << "a label is repeated";
    auto task = ds().task(problem);
    for (auto& l : labels) {
      ASSERT_TRUE(definitions_.count(l)) << "no goals/definitions/" << l << ".pddl";
      EXPECT_NO_THROW(task->compile_text(definitions_[l], l)) << l;
      // Nothing to do from the start would make the goal useless as a candidate.
      EXPECT_FALSE(task->compile_text(definitions_[l], l).holds(task->initial_state())) << l;
    }
  }
}

TEST_F(WorkshopDataset, ObservedPlansAlternateTurnsWithTheRobotWaitingAndEndInOneUtterance) {
  EXPECT_GE(ds().plans().size(), 20u);
  for (auto& p : ds().plans()) {
    SCOPED_TRACE(p.id);
    auto task = ds().task(p.problem_id);
    pddl::Simulation obs;
    ASSERT_NO_THROW(obs = pddl::simulate(*task, task->initial_state(), p.observed));
    ASSERT_FALSE(obs.actions.empty());
    for (size_t i = 0; i < obs.actions.size(); ++i) {
      std::string agent = agent_of(*task, obs.actions[i]);
      EXPECT_EQ(agent, i % 2 == 0 ? "human" : "robot") << "step " << i + 1;
      if (agent == "robot") {
        EXPECT_EQ(task->domain().actions[task->action(obs.actions[i]).schema].name, "wait");
      }
    }
    EXPECT_EQ(agent_of(*task, obs.actions.back()), "human") << "the human speaks after their own action";
    ASSERT_EQ(p.observed.utterances.size(), 1u);
    EXPECT_EQ(p.observed.utterances[0].index, static_cast<int>(obs.actions.size()));
  }
}

TEST_F(WorkshopDataset, CompletionsReachTheTrueGoalAndNoOtherCandidate) {
  for (auto& p : ds().plans()) {
    SCOPED_TRACE(p.id);
    auto task = ds().task(p.problem_id);
    ASSERT_TRUE(goal_sets_.count(p.problem_id));
    const auto& labels = goal_sets_[p.problem_id];
    ASSERT_NE(std::find(labels.begin(), labels.end(), p.tag), labels.end()) << "true goal not in the goal set";
    auto obs = pddl::simulate(*task, task->initial_state(), p.observed);
    pddl::Simulation comp;
    ASSERT_NO_THROW(comp = pddl::simulate(*task, obs.states.back(), p.completed));
    ASSERT_FALSE(comp.actions.empty());
    // The joint plan keeps alternating where the observed prefix stopped.
    for (size_t i = 0; i < comp.actions.size(); ++i)
      EXPECT_EQ(agent_of(*task, comp.actions[i]), (obs.actions.size() + i) % 2 == 0 ? "human" : "robot")
          << "completion step " << i + 1;
    // The true goal is reached by the last action, not before.
    const pddl::CompiledCondition truth = task->compile_text(definitions_[p.tag], p.tag);
    EXPECT_TRUE(truth.holds(comp.states.back()));
    for (size_t i = 0; i + 1 < comp.states.size(); ++i)
      EXPECT_FALSE(truth.holds(comp.states[i])) << "reached after " << i << " completion steps";
    auto truth_parts = conjuncts(definitions_[p.tag]);
    for (auto& l : labels) {
      if (l == p.tag) continue;
      auto parts = conjuncts(definitions_[l]);
      bool sub_goal = std::includes(truth_parts.begin(), truth_parts.end(), parts.begin(), parts.end());
      if (!sub_goal) {
        EXPECT_FALSE(task->compile_text(definitions_[l], l).holds(comp.states.back()))
            << "the completion also reaches " << l;
      }
    }
  }
}

}  // namespace
}  // namespace clips::data

// instructions.tsv: each plan's split and categories, and errors naming the
// file and line.
namespace {
struct WorkshopCopy {
  std::filesystem::path dir;
  WorkshopCopy() {
    dir = std::filesystem::temp_directory_path() / ("clips-instr-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::copy(std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop", dir,
                          std::filesystem::copy_options::recursive);
  }
  ~WorkshopCopy() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  std::string load_error(const std::string& table) const {
    std::ofstream((dir / "instructions.tsv").string()) << table;
    try {
      clips::data::Dataset::load(dir.string());
    } catch (const clips::InputError& e) {
      return e.what();
    }
    return "";
  }
};
}  // namespace

TEST(InstructionTable, SplitsAndCategoriesReachThePlans) {
  const auto ds = clips::data::Dataset::load(std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop");
  const auto& p = ds.plan("1.1.table");
  EXPECT_EQ(p.split, "dev");
  EXPECT_EQ(p.categories, (std::vector<std::string>{"qualifier", "other-action"}));
  int dev = 0, test = 0;
  for (const auto& q : ds.plans()) (q.split == "dev" ? dev : test) += 1;
  EXPECT_GT(dev, 0);
  EXPECT_GT(test, 0);
}

TEST(InstructionTable, BadRowsNameTheFileAndLine) {
  WorkshopCopy w;
  std::string e = w.load_error("plan\tsplit\tcategories\n1.1.table\ttrain\tdirect\n");
  EXPECT_NE(e.find("instructions.tsv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("must be dev or test"), std::string::npos) << e;
  e = w.load_error("plan\tsplit\tcategories\n9.9.nothing\tdev\tdirect\n");
  EXPECT_NE(e.find("no plan 9.9.nothing"), std::string::npos) << e;
  e = w.load_error("plan\tsplit\tcategories\n1.1.table\tdev\n");
  EXPECT_NE(e.find("expected 3 tab-separated columns"), std::string::npos) << e;
  e = w.load_error("plan\tsplit\n");
  EXPECT_NE(e.find("header"), std::string::npos) << e;
  EXPECT_EQ(w.load_error("plan\tsplit\tcategories\n1.1.table\ttest\tdirect, deixis\n"), "");
}

// The optional fourth column: what the instruction explicitly asks of the
// assistant, checked for its shape when the table loads.
TEST(InstructionTable, RequestedAtomsReachThePlans) {
  WorkshopCopy w;
  EXPECT_EQ(w.load_error("plan\tsplit\tcategories\trequested\n1.1.table\tdev\tdirect\t(holding human saw1)\n"
                         "3.3.birdhouse\ttest\tgoal\t\n"),
            "");
  const auto ds = clips::data::Dataset::load(w.dir.string());
  EXPECT_EQ(ds.plan("1.1.table").requested, "(holding human saw1)");
  EXPECT_EQ(ds.plan("3.3.birdhouse").requested, "");
  std::string e = w.load_error("plan\tsplit\tcategories\trequested\n1.1.table\tdev\tdirect\n");
  EXPECT_NE(e.find("expected 4 tab-separated columns"), std::string::npos) << e;
  e = w.load_error("plan\tsplit\tcategories\twanted\n");
  EXPECT_NE(e.find("header"), std::string::npos) << e;
  e = w.load_error("plan\tsplit\tcategories\trequested\n1.1.table\tdev\tdirect\tholding human saw1\n");
  EXPECT_NE(e.find("instructions.tsv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("ground atoms in parentheses"), std::string::npos) << e;
}
