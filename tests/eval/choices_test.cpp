// issue 63: one name table per kind of choice (util/choices.hpp), the names
// the bench composes from them, and docs/cli.md's table made from them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "domains/pack.hpp"
#include "engine/methods.hpp"
#include "engine/policies.hpp"
#include "eval/choices.hpp"
#include "eval/experiment.hpp"
#include "eval/methods.hpp"
#include "generated_section.hpp"
#include "inference/belief.hpp"
#include "util/choices.hpp"

namespace clips::eval {
namespace {

enum class Colour { Red, Blue };

TEST(Choices, ParseNamesAndListTheValidNamesOnABadOne) {
  util::Choices<Colour> t("colour", {{Colour::Red, "red", "warm", {"rouge"}}, {Colour::Blue, "blue", "cool", {}}});
  EXPECT_EQ(t.parse("red"), Colour::Red);
  EXPECT_EQ(t.parse("rouge"), Colour::Red);
  EXPECT_EQ(t.name(Colour::Blue), "blue");
  EXPECT_EQ(t.names(), (std::vector<std::string>{"red", "blue"}));
  EXPECT_EQ(t.help_text(), "red (warm) or blue (cool)");
  try {
    t.parse("green");
    FAIL() << "green parsed";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown colour 'green' (known: red, blue; also read: rouge)");
  }
  EXPECT_THROW(t.add({Colour::Blue, "rouge", "", {}}), std::logic_error);  // a spelling is taken once
}

TEST(Choices, TheOldParsersReadTheTables) {
  EXPECT_EQ(parse_method("both"), clips::Method::Clips);
  EXPECT_EQ(method_name(clips::Method::LanguageOnly), "lang_only");
  EXPECT_EQ(inference::parse_modality("language"), inference::Modality::UtteranceOnly);
  EXPECT_EQ(inference::to_string(inference::Modality::ActionOnly), "action");
  try {
    inference::parse_assistant_turns("some");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(known: taken, all)"), std::string::npos) << e.what();
  }
}

// The bench's composite names ("clips/pibar") come from the method and
// policy tables: a policy registered once is a method of every inference method.
TEST(Choices, BenchMethodNamesAreComposedFromTheTables) {
  const auto all = all_method_names();
  for (const char* n : {"clips", "lang_only", "action_only", "clips/qmdp_online", "action_only/pibar", "literal",
                        "literal_efficient", "literal_naive", "multimodal"})
    EXPECT_TRUE(is_method_name(n)) << n;
  EXPECT_FALSE(is_method_name("clips/qmdp_offline"));  // the default policy leaves the name bare
  EXPECT_FALSE(is_method_name("literal/pibar"));
  EXPECT_EQ(all.size(), 3u * 3u + 3u + 1u);
  try {
    make_method("clips/oracle");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("known: qmdp_offline, qmdp_online, pibar"), std::string::npos) << e.what();
  }

  // A decision policy registered for the live sessions is a bench method too,
  // under its own name, and leaves with its registration.
  engine::register_assistance({static_cast<Assistance>(99), "test_policy", "a policy only this test knows",
                               [](const engine::DecisionInput&) { return assist::Decision{}; }});
  struct Unregister {
    ~Unregister() { engine::unregister_assistance("test_policy"); }
  } unregister;
  EXPECT_TRUE(is_method_name("lang_only/test_policy"));
  EXPECT_EQ(assist_policy_choices().parse("test_policy").decide, static_cast<Assistance>(99));
  EXPECT_EQ(assist_policy_choices().parse("test_policy").episodes, Episodes::Offline);
  bool listed = false;
  for (const auto& [id, kind] : choice_catalogue())
    if (id == "assist") listed = kind.names().back() == "test_policy";
  EXPECT_TRUE(listed);
  EXPECT_NE(choices_markdown().find("| `assist` | `test_policy` | a policy only this test knows (decided at each "
                                    "assistant turn, offline) |"),
            std::string::npos);
  engine::unregister_assistance("test_policy");
  EXPECT_FALSE(is_method_name("lang_only/test_policy"));
  EXPECT_EQ(all_method_names().size(), 3u * 3u + 3u + 1u);
}

// docs/cli.md's "Named choices" table is the catalogue's; CLIPS_UPDATE_DOCS=1 rewrites it.
TEST(ChoicesDocs, TheCliPageListsEveryNameOfTheTables) {
  generated_docs::expect_generated_section("docs/cli.md", "choices", choices_markdown());
}

}  // namespace
}  // namespace clips::eval
