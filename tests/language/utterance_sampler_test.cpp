// The utterance sampler of `clips generate` (language/utterance_sampler.hpp):
// renaming qualifier values, the listener's part of a joint command, and
// which pool a phrasing is drawn from, with a stand-in scorer.
#include "domains/builtin/packs.hpp"
#include "language/utterance_sampler.hpp"

#include <gtest/gtest.h>

#include "commands/enumerate.hpp"
#include "pddl/parser.hpp"

namespace clips::language {
namespace {

const std::string kDomain = std::string(CLIPS_SOURCE_DIR) + "/data/domains/doors-keys-gems/domain.pddl";
const std::string kProblem = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems/problems/e1.pddl";

// Scores every continuation 0 except those containing `favourite`, which get +50.
class FavouriteModel : public lm::LanguageModel {
 public:
  explicit FavouriteModel(std::string favourite) : favourite_(std::move(favourite)) {}
  std::string name() const override { return "favourite"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    std::vector<double> out;
    for (const auto& r : batch) {
      prompts.push_back(r.prompt);
      out.push_back(r.continuation.find(favourite_) != std::string::npos ? 50.0 : 0.0);
    }
    return out;
  }
  std::vector<std::string> prompts;

 private:
  std::string favourite_;
};

commands::Command lifted(const std::vector<commands::Term>& ground, const commands::LanguageConfig& config,
                         const std::map<std::string, std::string>& colour) {
  auto qualifier = [&](const std::string& o) -> std::vector<commands::Term> {
    auto it = colour.find(o);
    if (it == colour.end()) return {};
    return {commands::Term{"iscolor", {o, it->second}}};
  };
  auto type = [](const std::string& o) { return o.substr(0, o.find_first_of("0123456789")); };
  return commands::lift_command(commands::extract_salient(ground, config, qualifier), config, type);
}

TEST(RenameValues, RenamesWholeWordsOneToOne) {
  EXPECT_EQ(rename_values("Yellow key, please: the yellow one.", {"yellow"}, {"red"}), "Red key, please: the red one.");
  // Simultaneous: a swap does not collapse.
  EXPECT_EQ(rename_values("the red and blue keys", {"red", "blue"}, {"blue", "red"}), "the blue and red keys");
  // Not inside other words.
  EXPECT_EQ(rename_values("a reddish key", {"red"}, {"blue"}), "a reddish key");
  // Two values onto one, or one onto two, would change what is asked.
  EXPECT_FALSE(rename_values("the red and blue keys", {"red", "blue"}, {"red", "red"}));
  EXPECT_FALSE(rename_values("two yellow keys", {"yellow", "yellow"}, {"red", "blue"}));
  EXPECT_EQ(rename_values("two yellow keys", {"yellow", "yellow"}, {"red", "red"}), "two red keys");
}

TEST(ListenerPart, DropsTheSpeakersOwnActions) {
  auto pack = domains::builtin_pack("doors-keys-gems");
  const auto& config = pack->language();
  const std::map<std::string, std::string> colour = {{"key2", "blue"}, {"gem1", "red"}};
  auto qualifier = [&](const std::string& o) -> std::vector<commands::Term> {
    auto it = colour.find(o);
    return it == colour.end() ? std::vector<commands::Term>{} : std::vector<commands::Term>{{"iscolor", {o, it->second}}};
  };
  auto type = [](const std::string& o) { return o.substr(0, o.find_first_of("0123456789")); };
  const auto joint = lifted({{"handover", {"robot", "human", "key2"}}, {"pickup", {"human", "gem1"}}}, config, colour);
  EXPECT_EQ(joint.llm_form(), "(handover you me key1) (pickup me gem1) where (iscolor key1 blue) (iscolor gem1 red)");
  const auto part = listener_part(joint, config, qualifier, type);
  ASSERT_TRUE(part);
  EXPECT_EQ(part->llm_form(), "(handover you me key1) where (iscolor key1 blue)");
  // Addressed to the listener only: the literal command is the command itself.
  EXPECT_FALSE(listener_part(lifted({{"pickup", {"robot", "key2"}}}, config, colour), config, qualifier, type));
}

TEST(UtteranceSampler, DrawsFromSameShapedCorpusEntriesWithTheValuesRenamed) {
  auto pack = domains::builtin_pack("doors-keys-gems");
  auto domain = std::make_shared<const pddl::Domain>(pddl::load_domain(kDomain));
  const pddl::Problem problem = pddl::load_problem(*domain, kProblem);
  // Every corpus phrasing of "hand me a yellow key" names yellow somewhere;
  // renamed for a pink key, the favourite text appears with pink.
  FavouriteModel lm("pink");
  UtteranceSampler sampler(pack, domain, lm);
  const auto cmd = lifted({{"handover", {"robot", "human", "key1"}}}, pack->language(), {{"key1", "pink"}});
  util::Rng rng(1);
  const Realisation r = sampler.realise(&cmd, false, problem, rng);
  EXPECT_EQ(r.pool, "corpus");
  EXPECT_GT(r.candidates, 20u);
  EXPECT_NE(r.text.find("pink"), std::string::npos) << r.text;
  EXPECT_EQ(r.command, "(handover you me key1) where (iscolor key1 pink)");
  ASSERT_FALSE(lm.prompts.empty());
  EXPECT_NE(lm.prompts.back().find("Input: (handover you me key1) where (iscolor key1 pink)\nOutput:"), std::string::npos);
  // The same generator state gives the same draw.
  util::Rng again(1);
  EXPECT_EQ(sampler.realise(&cmd, false, problem, again).text, r.text);
}

TEST(UtteranceSampler, TheEmptyCommandDrawsAnyUtteranceUnderTheEmptyPrompt) {
  auto pack = domains::builtin_pack("doors-keys-gems");
  auto domain = std::make_shared<const pddl::Domain>(pddl::load_domain(kDomain));
  const pddl::Problem problem = pddl::load_problem(*domain, kProblem);
  FavouriteModel lm("door");
  UtteranceSampler sampler(pack, domain, lm);
  util::Rng rng(2);
  const Realisation r = sampler.realise(nullptr, false, problem, rng);
  EXPECT_EQ(r.pool, "any");
  EXPECT_EQ(r.command, "");
  EXPECT_NE(r.text.find("door"), std::string::npos) << r.text;
  for (const char* colour : {"red", "yellow", "blue", "green"})
    EXPECT_EQ(r.text.find(colour), std::string::npos) << "the empty command names no colour: " << r.text;
  for (const auto& p : lm.prompts) EXPECT_EQ(p, "\n");
}

TEST(UtteranceSampler, AJointCommandWithoutSameShapedEntriesIsPhrasedByItsListenerPart) {
  auto pack = domains::builtin_pack("doors-keys-gems");
  auto domain = std::make_shared<const pddl::Domain>(pddl::load_domain(kDomain));
  const pddl::Problem problem = pddl::load_problem(*domain, kProblem);
  const std::map<std::string, std::string> colour = {{"key1", "yellow"}, {"gem1", "yellow"}};
  // Key and gem of one colour: no corpus entry renames one-to-one onto it.
  const auto joint = lifted({{"pickup", {"robot", "key1"}}, {"pickup", {"human", "gem1"}}}, pack->language(), colour);
  const auto part = lifted({{"pickup", {"robot", "key1"}}}, pack->language(), colour);
  FavouriteModel lm("yellow");
  UtteranceSampler sampler(pack, domain, lm);
  util::Rng rng(3);
  const Realisation r = sampler.realise(&joint, false, problem, rng, &part);
  EXPECT_EQ(r.pool, "listener part");
  EXPECT_NE(r.text.find("yellow"), std::string::npos) << r.text;
  // Scored under the joint command's own prompt.
  EXPECT_NE(lm.prompts.back().find("Input: " + joint.llm_form() + "\nOutput:"), std::string::npos);
  // Without the listener part, only texts naming no other colour remain.
  util::Rng again(3);
  const Realisation any = sampler.realise(&joint, false, problem, again);
  EXPECT_EQ(any.pool, "any");
  for (const char* other : {"red", "blue", "green", "Red", "Blue", "Green"})
    EXPECT_EQ(any.text.find(other), std::string::npos) << any.text;
}

}  // namespace
}  // namespace clips::language
