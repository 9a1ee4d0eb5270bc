#include "engine/options_test.hpp"

namespace options_test {
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

}  // namespace options_test
