// data/schema/pack.schema.json: every pack clips ships conforms to it, and the
// schema and the C++ reader (parse_pack_spec) agree on good and bad packs,
// naming the same field.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <fstream>
#include <regex>
#include <sstream>

#include "domains/pack.hpp"
#include "util/error.hpp"

namespace clips::domains {
namespace {

namespace fs = std::filesystem;

const std::string kSchema = CLIPS_SOURCE_DIR "/data/schema/pack.schema.json";

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += s + "\n";
  return out;
}

// The kitchen pack of docs/domains.md's worked example, as the docs test builds it.
std::string docs_example_pack() {
  const std::string doc = read(CLIPS_SOURCE_DIR "/docs/domains.md");
  const std::regex block("<!-- file: kitchen/pack.json -->\\s*\\n```json\\n([^`]*)```");
  std::smatch m;
  if (!std::regex_search(doc, m, block)) return "";
  return m[1];
}

// Every pack file in the source tree: the paper packs, the datasets', the
// test fixtures' and the docs example.
std::vector<std::pair<std::string, std::string>> shipped_packs() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const char* dir : {"data/domains", "data/datasets", "tests/fixtures"})
    if (fs::is_directory(fs::path(CLIPS_SOURCE_DIR) / dir))
      for (const auto& e : fs::directory_iterator(fs::path(CLIPS_SOURCE_DIR) / dir))
        if (fs::exists(e.path() / "pack.json")) out.push_back({(e.path() / "pack.json").string(), read(e.path() / "pack.json")});
  out.push_back({"docs/domains.md (kitchen/pack.json)", docs_example_pack()});
  return out;
}

TEST(PackSchema, EveryShippedPackConforms) {
  const auto packs = shipped_packs();
  ASSERT_GE(packs.size(), 4u);  // dkg, vh, workshop, the docs kitchen, and the test fixtures
  for (const auto& [name, text] : packs) {
    ASSERT_FALSE(text.empty()) << name;
    EXPECT_EQ(pack_schema_errors(text, name, kSchema), std::vector<std::string>{}) << name;
    EXPECT_NO_THROW(parse_pack_spec(text, name)) << name;
  }
}

// The schema's enums of named choices hold the names of the C++ tables
// (util/choices.hpp) the reader parses them with, in any order.
std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}
TEST(PackSchema, ItsChoiceEnumsAreTheNameTables) {
  const auto schema = nlohmann::json::parse(read(kSchema));
  const nlohmann::json* plans = nullptr;
  const nlohmann::json* literal = nullptr;
  // Found by walking: the property names are the pack fields' names.
  std::function<void(const nlohmann::json&)> walk = [&](const nlohmann::json& n) {
    if (n.is_object()) {
      if (n.contains("properties") && n["properties"].contains("plans") && n["properties"].contains("speaker_flag"))
        plans = &n["properties"]["plans"];
      if (n.contains("properties") && n["properties"].contains("methods") && n["properties"].contains("temperature"))
        literal = &n["properties"]["methods"]["items"];
      for (const auto& [k, v] : n.items()) walk(v);
    } else if (n.is_array()) {
      for (const auto& v : n) walk(v);
    }
  };
  walk(schema);
  ASSERT_TRUE(plans && literal);
  EXPECT_EQ(sorted((*plans)["enum"].get<std::vector<std::string>>()), sorted(speaker_plans_choices().names()));
  EXPECT_EQ(sorted((*literal)["enum"].get<std::vector<std::string>>()), sorted(literal_method_choices().names()));
}

TEST(PackSchema, TheDefaultPathIsTheSourceTreesSchema) {
  EXPECT_TRUE(fs::exists(pack_schema_path())) << pack_schema_path();
  EXPECT_EQ(pack_schema_errors(R"j({"domain": "k"})j", "t/pack.json"), std::vector<std::string>{});
}

// The C++ reader's error for a pack text ("" when it reads it).
std::string cpp_error(const std::string& text) {
  try {
    parse_pack_spec(text, "t/pack.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PackSchema, AgreesWithTheCppReaderOnGoodPacks) {
  for (const char* text : {
           R"j({"domain": "k"})j",
           R"j({"$schema": "../data/schema/pack.schema.json", "domain": "k", "comment": "c"})j",
           R"j({"domain": "k", "roles": {"comment": "c", "principal": "cook", "assistant": "helper", "turns": "alternate",
                "noop_action": "idle", "turn_predicate": "turn", "agent_type": "person", "horizon": 40}})j",
           R"j({"domain": "k", "roles": {"principal": "a", "assistant": "b", "turns": ["b", "a", "c"]}})j",
           R"j({"domain": "k", "roles": {"turns": "domain"}})j",
           R"j({"domain": "k", "language": {"comment": "c", "salient_actions": [{"comment": "c", "action": "take", "focal_arg": 2}],
                "qualifier": {"comment": "c", "predicate": "iscolor"}, "speaker": {"comment": "c", "object": "human", "pronoun": "me"},
                "goal_atoms": {"comment": "c", "take": ["(holding $1 $2)"]}}})j",
           R"j({"domain": "k", "cost_profiles": [{"comment": "c", "profiles": [{"name": "p",
                "costs": {"comment": "c", "human": {"comment": "c", "move": 2}}}]}]})j",
           R"j({"domain": "k", "scene": "cards", "scene_colours": {"comment": "c", "plate": "#a8c8f5"}})j",
       }) {
    EXPECT_EQ(cpp_error(text), "") << text;
    EXPECT_EQ(pack_schema_errors(text, "t/pack.json", kSchema), std::vector<std::string>{}) << text;
  }
}

TEST(PackSchema, AgreesWithTheCppReaderOnBadPacksAndNamesTheSameField) {
  const std::vector<std::pair<const char*, std::string>> bad = {
      {R"j({"roles": {}})j", "domain"},                                                   // required field missing
      {R"j({"domain": "k", "goal": {}})j", "goal"},                                        // misspelt top-level field
      {R"j({"domain": "k", "roles": {"principle": "cook"}})j", "roles.principle"},        // misspelt field
      {R"j({"domain": "k", "goals": {"source": "object"}})j", "goals.source"},            // wrong enum value
      {R"j({"domain": "k", "roles": {"horizon": "40"}})j", "roles.horizon"},              // wrong type
      {R"j({"domain": "k", "roles": {"horizon": 0}})j", "roles.horizon"},                 // out of range
      {R"j({"domain": "k", "roles": {"turns": "sometimes"}})j", "roles.turns"},           // neither form
      {R"j({"domain": "k", "roles": {"turns": ["human"]}})j", "roles.turns"},             // too short an order
      {R"j({"domain": "k", "roles": {"turn_predicate": ""}})j", "roles.turn_predicate"},  // empty name
      {R"j({"domain": "k", "comment": 5})j", "comment"},                                   // comments are text
      {R"j({"domain": "k", "scene": "grid3d"})j", "scene"},
      {R"j({"domain": "k", "scene_colours": {"plate": "#12345"}})j", "scene_colours.plate"},
      {R"j({"domain": "k", "literal_listener": {"methods": ["literal_fancy"]}})j", "literal_listener.methods[0]"},
      {R"j({"domain": "k", "assistance_options": [{"action": "take", "object_arg": 1}]})j", "assistance_options[0].object_arg"},
      {R"j({"domain": "k", "inference": {"temperature_prior": {"shape": 0}}})j", "inference.temperature_prior.shape"},
      {R"j({"domain": "k", "inference": {"rollout": {"kind": "beam"}}})j", "inference.rollout.kind"},
      {R"j({"domain": "k", "cost_profiles": []})j", "cost_profiles"},
      {R"j({"domain": "k", "fewshot": {"fille": "x.tsv"}})j", "fewshot.fille"},
      {R"j({"domain": "k", "grounding": {"first_param_fastest": "yes"}})j", "grounding.first_param_fastest"},
      {R"j({"domain": "k", "language": {"salient_actions": [{"action": "take", "focal": 2}]}})j", "salient_actions[0]"},
      {R"j({"domain": "k", "language": {"salient_actions": [{"action": "t", "focal_arg": 1}], "qualifier": {"predicate": "c", "arg": 1}}})j",
       "qualifier.arg"},
      {R"j({"domain": "k", "language": {"salient_actions": [{"action": "t", "focal_arg": 1}], "listener": {"object": "r", "pronoun": "you", "name": "x"}}})j",
       "listener.name"},
      {R"j({"domain": "k", "language": {"salient_actions": [{"action": "t", "focal_arg": 1}], "printed_args": "some"}})j", "printed_args"},
  };
  for (const auto& [text, field] : bad) {
    const std::string cpp = cpp_error(text);
    const auto schema = pack_schema_errors(text, "t/pack.json", kSchema);
    EXPECT_NE(cpp, "") << "the C++ reader accepts " << text;
    EXPECT_FALSE(schema.empty()) << "the schema accepts " << text;
    EXPECT_NE(cpp.find(field), std::string::npos) << text << "\nC++: " << cpp;
    bool named = false;
    for (const auto& e : schema) named = named || e.find(field) != std::string::npos;
    EXPECT_TRUE(named) << text << "\nschema:\n" << joined(schema);
  }
}

}  // namespace
}  // namespace clips::domains
