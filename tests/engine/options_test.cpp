#include "engine/options_test.hpp"

#include "generated_section.hpp"

namespace options_test {
TEST(ParticleOptionTable, NamesRangesAndTheStructAgree) {
  clips::ParticleOptions o;
  for (const auto& opt : clips::engine::option_table()) {
    // Every default reads back and parses again.
    const std::string text = clips::engine::option_text(o, opt.name);
    EXPECT_NO_THROW(clips::engine::set_option(o, opt.name, text)) << opt.name;
    EXPECT_EQ(clips::engine::cli_flag(opt).substr(0, 2), "--");
  }
  EXPECT_EQ(clips::engine::option_table().size(), 8u);
  clips::engine::set_option(o, "ess_threshold", "0.25");
  clips::engine::set_option(o, "particle_seed", "18446744073709551615");
  clips::engine::set_option(o, "rejuvenate", "utterances");
  EXPECT_EQ(o.ess_threshold, 0.25);
  EXPECT_EQ(o.particle_seed, UINT64_MAX);
  EXPECT_EQ(o.rejuvenate, "utterances");
  EXPECT_THROW(clips::engine::set_option(o, "particle_seed", "18446744073709551616"), clips::InputError);
  EXPECT_THROW(clips::engine::set_option(o, "ess_threshold", "nan"), clips::InputError);
  EXPECT_THROW(clips::engine::set_option(o, "particles", " 5"), clips::InputError);
  try {
    clips::engine::set_option(o, "colour", "red");
    ADD_FAILURE() << "an unknown name was accepted";
  } catch (const clips::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown option 'colour'"), std::string::npos) << e.what();
  }
  // The struct check gives the same message as the text parser.
  clips::ParticleOptions bad;
  bad.proposal_groups = 0;
  try {
    clips::engine::check_options(bad);
    ADD_FAILURE() << "proposal_groups 0 was accepted";
  } catch (const clips::InputError& e) {
    EXPECT_STREQ(e.what(), "proposal_groups must be an integer from 1 to 64, got 0");
  }
}

// An option registered at run time is a row like the others: its range in
// the message, its value as text in registered_options, its default when
// unset, refused once taken back.
TEST(ParticleOptionTable, ARegisteredOptionIsARowUntilTakenBack) {
  using clips::engine::EngineOption;
  EngineOption o;
  o.name = "test_offset";
  o.kind = EngineOption::Kind::Integer;
  o.help = "an offset";
  o.default_text = "-2";
  o.minimum = -5;
  o.maximum = 5;
  clips::engine::register_option(o);
  clips::ParticleOptions p;
  EXPECT_EQ(clips::engine::option_text(p, "test_offset"), "-2");
  clips::engine::set_option(p, "test_offset", "-4");
  EXPECT_EQ(p.registered_options.at("test_offset"), "-4");
  EXPECT_EQ(clips::engine::registered_option_values(p).at("test_offset"), "-4");
  for (const std::string bad : {"6", "1.5", "", "--1", "1e2"}) {
    try {
      clips::engine::set_option(p, "test_offset", bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const clips::InputError& e) {
      EXPECT_EQ(std::string(e.what()), "test_offset must be an integer from -5 to 5, got " + bad);
    }
  }
  EXPECT_NO_THROW(clips::engine::check_options(p));
  EXPECT_THROW(clips::engine::register_option(o), clips::InputError);  // taken
  clips::engine::unregister_option("test_offset");
  EXPECT_THROW(clips::engine::check_options(p), clips::InputError);  // a value for no option
  EXPECT_THROW(clips::engine::unregister_option("test_offset"), clips::InputError);
  EXPECT_EQ(clips::engine::option_table().size(), 8u);
}

// docs/library.md's table of the session options is the engine's table;
// CLIPS_UPDATE_DOCS=1 rewrites it.
TEST(ParticleOptionTable, TheLibraryPageListsEverySessionOption) {
  const std::string want = clips::engine::session_options_markdown();
  for (const auto& o : clips::engine::session_option_table())
    EXPECT_NE(want.find("| `" + o.name + "` |"), std::string::npos) << o.name;
  clips::generated_docs::expect_generated_section("docs/library.md", "options", want);
}

}  // namespace options_test
