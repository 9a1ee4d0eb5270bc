// StateGraph: ids, successor lists in the task's action order, and the same
// graph whether one thread or several expand it.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <thread>
#include <vector>

#include "data/dataset.hpp"
#include "search/state_graph.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

std::shared_ptr<const pddl::Task> example_task() {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  return ds.task("e2");
}

}  // namespace

TEST(StateGraph, SuccessorsAreTheApplicableActionsInOrder) {
  auto task = example_task();
  search::StateGraph g(task);
  const pddl::State s0 = task->initial_state();
  EXPECT_EQ(g.find(s0.data()), -1);
  const int root = g.insert(s0.data());
  EXPECT_EQ(root, 0);
  EXPECT_EQ(g.insert(s0.data()), 0);
  EXPECT_EQ(g.find(s0.data()), 0);
  // Breadth-first over a few hundred states: every list matches the task.
  std::vector<int> frontier = {root};
  std::set<int> seen = {root};
  for (size_t i = 0; i < frontier.size() && i < 400; ++i) {
    const int id = frontier[i];
    const pddl::State s{std::vector<uint64_t>(g.state(id), g.state(id) + g.words())};
    const auto acts = task->applicable_actions(s);
    const auto succ = g.successors(id);
    ASSERT_EQ(succ.size(), acts.size());
    for (size_t k = 0; k < acts.size(); ++k) {
      EXPECT_EQ(succ[k].action, acts[k]);
      const pddl::State c = task->apply(s, acts[k]);
      EXPECT_EQ(g.find(c.data()), succ[k].child);
      EXPECT_TRUE(std::equal(c.words.begin(), c.words.end(), g.state(succ[k].child)));
      if (seen.insert(succ[k].child).second) frontier.push_back(succ[k].child);
    }
    // A second call returns the same list.
    const auto again = g.successors(id);
    EXPECT_EQ(again.data(), succ.data());
  }
  EXPECT_GT(g.size(), 400);
}

TEST(StateGraph, ConcurrentExpansionBuildsTheSameGraph) {
  // Threads expand overlapping parts of the state space at once (run under
  // ThreadSanitizer too): afterwards every list agrees with the task and the
  // set of states equals a sequential exploration's.
  auto task = example_task();
  const int depth = 14;
  // Expands every state within `depth` steps, level by level, starting each
  // level at a different offset per thread so the threads collide; returns
  // the expanded ids.
  auto explore = [&](search::StateGraph& g, size_t offset) {
    std::vector<int> level = {g.insert(task->initial_state().data())}, expanded;
    for (int d = 0; d < depth; ++d) {
      std::vector<int> next;
      for (size_t j = 0; j < level.size(); ++j) {
        const int id = level[(j + offset) % level.size()];
        expanded.push_back(id);
        for (const auto& sc : g.successors(id)) next.push_back(sc.child);
      }
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      level = std::move(next);
    }
    return expanded;
  };
  search::StateGraph sequential(task);
  const std::vector<int> expanded = explore(sequential, 0);
  search::StateGraph shared(task);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < 4; ++t) threads.emplace_back([&, t] { explore(shared, 97 * t); });
  for (auto& th : threads) th.join();
  ASSERT_EQ(shared.size(), sequential.size());
  EXPECT_GT(shared.size(), 2000);
  for (int id = 0; id < shared.size(); ++id) ASSERT_GE(sequential.find(shared.state(id)), 0);
  for (int other : expanded) {
    const int id = shared.find(sequential.state(other));
    ASSERT_GE(id, 0);
    const auto a = shared.successors(id);
    const auto b = sequential.successors(other);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].action, b[k].action);
      EXPECT_TRUE(std::equal(shared.state(a[k].child), shared.state(a[k].child) + shared.words(),
                             sequential.state(b[k].child)));
    }
  }
}
