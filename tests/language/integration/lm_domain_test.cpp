// The embedded LM's description of a domain read from PDDL and the command
// model (language/lm_domain.hpp), on the workshop domain, which ships no
// hand-written corpus: the generated corpus trains a model that understands it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "lm/embedded_model.hpp"
#include "language/lm_domain.hpp"
#include "pddl/parser.hpp"

namespace clips::language {
namespace {

const std::string kWorkshop = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop";

commands::LanguageConfig workshop_commands() {
  commands::LanguageConfig c;
  c.domain = "workshop";
  c.salient_actions = {{"pickup", 1, 2}, {"handover", 1, 3}, {"putdown", 1, 2}};
  c.qualifier = "issize";
  return c;
}

lm::DomainDescription workshop_description(const std::vector<std::string>& qualifiers) {
  const pddl::Domain d = pddl::load_domain(kWorkshop + "/domain.pddl");
  const pddl::Problem p = pddl::load_problem(d, kWorkshop + "/problems/1.pddl", false);
  return describe_for_language_model(d, p, workshop_commands(), qualifiers);
}

TEST(LmDomain, DescribesTheWorkshopForTheCorpusGenerator) {
  const lm::DomainDescription d = workshop_description({"issize", "ismaterial"});
  auto handover = std::find_if(d.actions.begin(), d.actions.end(), [](const auto& a) { return a.name == "handover"; });
  ASSERT_NE(handover, d.actions.end());
  EXPECT_EQ(handover->parameter_types, (std::vector<std::string>{"agent", "agent", "item", "station"}));
  EXPECT_EQ(d.parent_type.at("plank"), "part");
  EXPECT_EQ(d.parent_type.at("part"), "item");
  EXPECT_EQ(d.qualifiers.size(), 12u);  // six items, each with a size and a material
  EXPECT_EQ(d.command_actions.size(), 3u);
  EXPECT_EQ(d.speaker, "human");
  // Only the config's own qualifier when none are named.
  EXPECT_EQ(workshop_description({}).qualifiers.size(), 6u);
}

TEST(LmDomain, EmbeddedModelFromTheGeneratedCorpusReadsSizes) {
  lm::EmbeddedModelOptions o = lm::embedded_options_for_domain(workshop_description({"issize", "ismaterial"}));
  o.cache_dir = "off";
  lm::EmbeddedLanguageModel model(o);
  auto prompt = [](const std::string& cmd) { return "Input: " + cmd + "\nOutput:"; };
  const std::string u = " Can you hand me the small plank?\n";
  const double small = model.score_one(prompt("(handover you me plank1) where (issize plank1 small)"), u);
  const double big = model.score_one(prompt("(handover you me plank1) where (issize plank1 big)"), u);
  const double leg = model.score_one(prompt("(handover you me leg1) where (issize leg1 small)"), u);
  EXPECT_GT(small, big + 2.0);
  EXPECT_GT(small, leg + 2.0);
}

}  // namespace
}  // namespace clips::language
