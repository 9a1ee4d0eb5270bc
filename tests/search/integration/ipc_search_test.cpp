#include "search/ipc_search_test.hpp"

namespace ipc_search_test {
TEST(StateGraph, AStateWithMoreThan65535SuccessorsIsStored) {
  // 260 x 260 = 67,600 applicable actions in the initial state.
  std::string objs;
  for (int i = 0; i < 260; ++i) objs += " o" + std::to_string(i);
  auto t = task_of(R"((define (domain wide) (:requirements :strips)
    (:predicates (done) (item ?x))
    (:action mark :parameters (?x ?y) :precondition (and (item ?x) (item ?y)) :effect (done))))",
                   "(define (problem w) (:domain wide) (:objects" + objs + ") (:init" +
                       [&] {
                         std::string s;
                         for (int i = 0; i < 260; ++i) s += " (item o" + std::to_string(i) + ")";
                         return s;
                       }() +
                       ") (:goal (done)))");
  ASSERT_EQ(t->num_actions(), 67600);
  search::StateGraph g(t);
  const int root = g.insert(t->initial_state().data());
  const auto succ = g.successors(root);
  ASSERT_EQ(succ.size(), 67600u);
  EXPECT_EQ(succ.front().action, 0);
  EXPECT_EQ(succ.back().action, 67599);
  // Every successor is the one state where (done) holds; a second wide
  // state after it is stored apart.
  EXPECT_EQ(succ.front().child, succ.back().child);
  EXPECT_EQ(g.successors(succ.front().child).size(), 67600u);
  EXPECT_EQ(g.successors(root).size(), 67600u);
}

}  // namespace ipc_search_test
