// The 'task' cost profile reads the domain's own (total-cost) increases: on a
// domain without total-cost it is an error, never a silent cost of 0.
#include <gtest/gtest.h>

#include <memory>

#include "data/dataset.hpp"
#include "model/spec.hpp"
#include "pddl/parser.hpp"
#include "test_paths.hpp"

namespace clips::model {
namespace {

std::shared_ptr<const pddl::Task> example_task(const std::string& dir, const std::string& problem) {
  auto d = std::make_shared<pddl::Domain>(pddl::load_domain(paths::examples_dir() + "/" + dir + "/domain.pddl"));
  auto p = std::make_shared<pddl::Problem>(pddl::load_problem(*d, paths::examples_dir() + "/" + dir + "/" + problem));
  return std::make_shared<const pddl::Task>(d, p);
}

TEST(TaskCosts, DomainWithoutTotalCostIsRefused) {
  auto task = example_task("doors-keys-gems", "problems/e1.pddl");
  ASSERT_FALSE(task->domain().total_cost);
  try {
    Specification spec(task, "(has human gem1)", task_costs_profile());
    FAIL() << "accepted the 'task' profile without total-cost";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("total-cost"), std::string::npos) << e.what();
  }
  // Unit costs still work there.
  EXPECT_NO_THROW(Specification(task, "(has human gem1)", unit_profile()));
}

TEST(TaskCosts, DomainWithTotalCostUsesItsCosts) {
  auto task = example_task("blocks", "p1.pddl");
  ASSERT_TRUE(task->domain().total_cost);
  Specification spec(task, "(and)", task_costs_profile());
  ASSERT_GT(task->num_actions(), 0);
  for (pddl::ActionId a = 0; a < task->num_actions(); ++a) EXPECT_EQ(spec.cost(a), task->action(a).cost);
}

}  // namespace
}  // namespace clips::model
