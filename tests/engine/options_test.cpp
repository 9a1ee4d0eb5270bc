#include "engine/options_test.hpp"

namespace options_test {
TEST(ParticleOptionTable, NamesRangesAndTheStructAgree) {
  clips::ParticleOptions o;
  for (const auto& opt : clips::engine::particle_option_table()) {
    // Every default reads back and parses again.
    const std::string text = clips::engine::particle_option_text(o, opt.name);
    EXPECT_NO_THROW(clips::engine::set_particle_option(o, opt.name, text)) << opt.name;
    EXPECT_EQ(clips::engine::cli_flag(opt).substr(0, 2), "--");
  }
  EXPECT_EQ(clips::engine::particle_option_table().size(), 8u);
  clips::engine::set_particle_option(o, "ess_threshold", "0.25");
  clips::engine::set_particle_option(o, "particle_seed", "18446744073709551615");
  clips::engine::set_particle_option(o, "rejuvenate", "utterances");
  EXPECT_EQ(o.ess_threshold, 0.25);
  EXPECT_EQ(o.particle_seed, UINT64_MAX);
  EXPECT_EQ(o.rejuvenate, "utterances");
  EXPECT_THROW(clips::engine::set_particle_option(o, "particle_seed", "18446744073709551616"), clips::InputError);
  EXPECT_THROW(clips::engine::set_particle_option(o, "ess_threshold", "nan"), clips::InputError);
  EXPECT_THROW(clips::engine::set_particle_option(o, "particles", " 5"), clips::InputError);
  try {
    clips::engine::set_particle_option(o, "colour", "red");
    ADD_FAILURE() << "an unknown name was accepted";
  } catch (const clips::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown particle option 'colour'"), std::string::npos) << e.what();
  }
  // The struct check gives the same message as the text parser.
  clips::ParticleOptions bad;
  bad.proposal_groups = 0;
  try {
    clips::engine::check_particle_options(bad);
    ADD_FAILURE() << "proposal_groups 0 was accepted";
  } catch (const clips::InputError& e) {
    EXPECT_STREQ(e.what(), "proposal_groups must be an integer from 1 to 64, got 0");
  }
}

}  // namespace options_test
