// The one particle option table (engine/options.hpp): the CLI's flags,
// Python's keywords and the server's JSON read the same names and give the
// same message for the same bad value.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "clips/clips.hpp"
#include "engine/options.hpp"
#include "language/listener.hpp"
#include "serve/service.hpp"
#include "run_command.hpp"
#include "test_paths.hpp"

namespace {

using nlohmann::json;

const std::string kDataset = clips::paths::examples_dir() + "/doors-keys-gems";

using clips::tests::output_of;

// One bad value as each front end spells it, and the message all must give.
struct BadValue {
  std::string name;
  std::string cli;     // the flag's text
  std::string python;  // a Python literal
  json json_value;
  std::string message;
};

const std::vector<BadValue> kBad = {
    {"ess_threshold", "1.5", "1.5", 1.5, "ess_threshold must be a number from 0 to 1, got 1.5"},
    {"particles", "2000000", "2000000", 2000000, "particles must be an integer from 0 to 1000000, got 2000000"},
    {"rejuvenation_moves", "101", "101", 101, "rejuvenation_moves must be an integer from 0 to 100, got 101"},
    {"proposal_groups", "0", "0", 0, "proposal_groups must be an integer from 1 to 64, got 0"},
    {"rejuvenate", "sometimes", "'sometimes'", "sometimes",
     "rejuvenate must be one of evidence, utterances, resampling, got 'sometimes'"},
    {"particle_filters", "some", "'some'", "some", "particle_filters must be one of all, clips, got 'some'"},
    {"particle_estimate", "counts", "'counts'", "counts",
     "particle_estimate must be one of support, weights, got 'counts'"},
};

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

TEST(ParticleOptionTable, ABadValueGivesTheSameErrorFromCliPythonAndServer) {
  const std::string clips = std::string(CLIPS_BINARY_DIR) + "/clips";
  // Python: one line per case, the exception's type and text.
  const std::string script = std::string(CLIPS_BINARY_DIR) + "/options_test.py";
  {
    std::ofstream f(script);
    f << "import clips_assist\n";
    for (const auto& b : kBad)
      f << "try:\n    clips_assist.Session.open_dataset(\"" << kDataset << "\", \"e1\", " << b.name << "=" << b.python
        << ")\n    print('accepted')\nexcept clips_assist.InputError as e:\n    print('InputError:', e)\n";
  }
  const std::string py = output_of("PYTHONPATH=" + std::string(CLIPS_BINARY_DIR) + "/python /usr/bin/python3 " + script);
  auto lm = clips::language::make_language_model("embedded");
  clips::serve::Service service({kDataset}, {}, lm);
  size_t line_start = 0;
  for (const auto& b : kBad) {
    SCOPED_TRACE(b.name);
    // CLI: the flag is refused at parse time (exit 2) with the table's message.
    const std::string flag = "--" + [&] {
      std::string f = b.name;
      for (auto& c : f)
        if (c == '_') c = '-';
      return f;
    }();
    const std::string cli = output_of(clips + " infer --dataset " + kDataset + " --plan e1.1.keys " + flag + " " + b.cli);
    EXPECT_NE(cli.find(b.message), std::string::npos) << cli;
    EXPECT_NE(cli.find(flag), std::string::npos) << cli;
    // Python: InputError with the message.
    const size_t eol = py.find('\n', line_start);
    const std::string line = py.substr(line_start, eol == std::string::npos ? std::string::npos : eol - line_start);
    line_start = eol == std::string::npos ? py.size() : eol + 1;
    EXPECT_EQ(line, "InputError: " + b.message) << py;
    // Server: 400 naming the field, with the message.
    const json body = {{"dataset", "doors-keys-gems"}, {"problem", "e1"}, {"inference", {{b.name, b.json_value}}}};
    const auto reply = service.handle("POST", "/api/sessions", body.dump());
    EXPECT_EQ(reply.status, 400) << reply.body;
    EXPECT_EQ(json::parse(reply.body)["error"], "field 'inference': " + b.message) << reply.body;
  }
}

TEST(ParticleOptionTable, TheServerTakesASessionsParticleOptions) {
  auto lm = clips::language::make_language_model("embedded");
  clips::serve::Service service({kDataset}, {}, lm);
  const json body = {{"dataset", "doors-keys-gems"},
                     {"problem", "e1"},
                     {"inference", {{"particles", 16}, {"particle_seed", 3}, {"particle_filters", "clips"}}}};
  const auto created = service.handle("POST", "/api/sessions", body.dump());
  ASSERT_EQ(created.status, 201) << created.body;
  EXPECT_EQ(json::parse(created.body)["inference"]["particles"], 16);
  // Over the server's cap, and not an object.
  auto r = service.handle(
      "POST", "/api/sessions",
      json{{"dataset", "doors-keys-gems"}, {"problem", "e1"}, {"inference", {{"particles", 20000}}}}.dump());
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(r.body.find("at most 10000"), std::string::npos) << r.body;
  r = service.handle("POST", "/api/sessions",
                     json{{"dataset", "doors-keys-gems"}, {"problem", "e1"}, {"inference", 5}}.dump());
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(r.body.find("field 'inference'"), std::string::npos) << r.body;
}

}  // namespace
