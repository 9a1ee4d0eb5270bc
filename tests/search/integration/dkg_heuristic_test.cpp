#include "search/dkg_heuristic_test.hpp"

TEST(DkgDistanceHeuristic, AdmissibleAgainstExactCostOnHandMaps) {
  std::vector<std::pair<Hand, std::vector<std::string>>> cases;
  cases.push_back({make_map_a(), {"(has human gem1)", "(has human key1)", "(has robot key1)"}});
  cases.push_back({make_map_b(true), {"(has human gem1)"}});
  cases.push_back({make_map_c(), {"(has human gem1)", "(has human key2)", "(or (has human key2) (has robot key1))"}});
  cases.push_back({make_map_d(), {"(has human gem1)", "(has human key2)"}});
  std::mt19937 rng(11);
  int checked = 0;
  for (auto& [h, goals] : cases)
    for (auto& g : goals)
      for (int profile = 1; profile <= 4; ++profile) {
        auto spec = h.spec(g, profile);
        DkgDistanceHeuristic d;
        d.prepare(spec, h.task->initial_state());
        for (int i = 0; i < 8; ++i) {
          State s = random_walk(*h.task, h.task->initial_state(), i * 3, rng);
          Exact ex = exact_cost(*h.task, spec, s, 400000);
          if (!ex.complete) continue;
          double v = d.estimate(s);
          std::vector<pddl::ActionId> acts;
          h.task->applicable_actions(s.data(), acts);
          for (auto a : acts)
            EXPECT_LE(v, spec.cost(a) + d.estimate(h.task->apply(s, a)) + kEps) << g << " " << h.task->action_name(a);
          if (ex.cost == model::kInf) continue;  // any value is admissible
          EXPECT_LE(v, ex.cost + kEps) << g << " C" << profile << "\n" << h.task->state_str(s);
          ++checked;
        }
      }
  EXPECT_GT(checked, 100);
}
