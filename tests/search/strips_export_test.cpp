#include "search/strips_export_test.hpp"

TEST(StripsExport, CostScale) {
  for (int c = 1; c <= 4; ++c) {
    std::vector<double> costs;
    auto prof = fixtures::dkg_profile(c);
    for (auto& [k, v] : prof.costs) costs.push_back(v);
    EXPECT_EQ(domains::integer_cost_scale(costs), 5) << "C" << c;
  }
  EXPECT_EQ(domains::integer_cost_scale({1, 2, 5}), 1);
  EXPECT_EQ(domains::integer_cost_scale({0.25, 1}), 4);
  EXPECT_EQ(domains::integer_cost_scale({1.0 / 3, 0.5}), 6);
  EXPECT_THROW(domains::integer_cost_scale({std::sqrt(2.0)}), InputError);
  EXPECT_THROW(domains::integer_cost_scale({-1}), InputError);
  auto task = examples().task("e1");
  EXPECT_EQ(domains::dkg::export_strips(*task, task->initial_state(), "(has human gem2)", model::unit_profile()).cost_scale,
            1);
  // The scaled costs appear in the domain: human wait 0.6 -> 3, human pickup 5 -> 25.
  auto ex = domains::dkg::export_strips(*task, task->initial_state(), "(has human gem2)", fixtures::dkg_profile(1));
  EXPECT_NE(ex.domain.find("(:action wait-human"), std::string::npos);
  EXPECT_NE(ex.domain.find("(increase (total-cost) 3)"), std::string::npos);
  EXPECT_NE(ex.domain.find("(increase (total-cost) 25)"), std::string::npos);
  EXPECT_NE(ex.domain.find(":requirements :strips :typing :action-costs"), std::string::npos);
  EXPECT_NE(ex.problem.find("(:metric minimize (total-cost))"), std::string::npos);
}

TEST(StripsExport, ActionMapping) {
  EXPECT_EQ(domains::dkg::to_original_action("(move-up-human c_5_3 c_5_2)"), "(up human)");
  EXPECT_EQ(domains::dkg::to_original_action("(move-right-robot c_5_3 c_6_3)"), "(right robot)");
  EXPECT_EQ(domains::dkg::to_original_action("(pickup-robot key1 c_1_3)"), "(pickup robot key1)");
  EXPECT_EQ(domains::dkg::to_original_action("(unlock-human key1 door1 c_3_2 c_3_1)"), "(unlock human key1 door1)");
  EXPECT_EQ(domains::dkg::to_original_action("(handover-robot-human key2 c_5_4 c_5_3)"), "(handover robot human key2)");
  EXPECT_EQ(domains::dkg::to_original_action("(wait-robot)"), "(wait robot)");
  EXPECT_EQ(domains::dkg::to_original_action("(WAIT-HUMAN)"), "(wait human)");
  for (const char* bad : {"(up human)", "(move-up-human c_1_1)", "(handover-human key1 c_1_1 c_1_2)", "wait-human",
                          "(pickup- key1 c_1_1)"})
    EXPECT_THROW(domains::dkg::to_original_action(bad), InputError) << bad;
}
