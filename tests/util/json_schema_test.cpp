// The compact JSON Schema validator (util/json_schema.hpp): each keyword it
// implements, error paths in the C++ readers' style, and refusing schemas
// that use a keyword it does not implement.
#include "util/json_schema.hpp"

#include <gtest/gtest.h>

#include "util/error.hpp"

namespace clips::util {
namespace {

using nlohmann::json;

std::vector<std::string> errors(const json& schema, const json& doc) {
  std::vector<std::string> out;
  for (const auto& e : JsonSchema(schema, "test.schema.json").validate(doc)) out.push_back(e.str());
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += s + "\n";
  return out;
}

bool mentions(const std::vector<std::string>& v, const std::string& part) {
  for (const auto& s : v)
    if (s.find(part) != std::string::npos) return true;
  return false;
}

const json kSchema = json::parse(R"j({
  "$schema": "https://json-schema.org/draft/2020-12/schema",
  "title": "t",
  "type": "object",
  "required": ["name"],
  "additionalProperties": false,
  "properties": {
    "name": {"$ref": "#/$defs/name"},
    "kind": {"type": "string", "enum": ["a", "b"]},
    "count": {"type": "integer", "minimum": 1, "maximum": 10},
    "scale": {"type": "number", "exclusiveMinimum": 0},
    "tags": {"type": "array", "items": {"$ref": "#/$defs/name"}, "minItems": 1, "uniqueItems": true},
    "mode": {"oneOf": [{"type": "string", "enum": ["x"]}, {"type": "array", "minItems": 2}]},
    "colours": {
      "type": "object",
      "propertyNames": {"pattern": "[^0-9]$"},
      "properties": {"comment": {"type": "string"}},
      "additionalProperties": {"type": "string", "pattern": "^#[0-9a-f]{6}$"}
    },
    "fixed": {"const": 3}
  },
  "$defs": {"name": {"type": "string", "minLength": 1}}
})j");

TEST(JsonSchema, AConformingDocumentHasNoErrors) {
  EXPECT_TRUE(errors(kSchema, json::parse(R"j({"name": "n", "kind": "a", "count": 3, "scale": 0.5, "tags": ["x", "y"],
                                                "mode": "x", "colours": {"comment": "c", "plate": "#a0b0c0"},
                                                "fixed": 3})j"))
                  .empty());
  // An integer is any number without a fractional part, 3.0 too.
  EXPECT_TRUE(errors(kSchema, json::parse(R"j({"name": "n", "count": 3.0, "mode": [1, 2]})j")).empty());
}

TEST(JsonSchema, EachKeywordNamesTheFieldAndWhatItExpects) {
  auto e = errors(kSchema, json::parse(R"j({"kind": "c"})j"));
  EXPECT_TRUE(mentions(e, "name: missing (required)")) << joined(e);
  EXPECT_TRUE(mentions(e, "kind: expected one of: \"a\", \"b\"")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "", "nmae": 1})j"));
  EXPECT_TRUE(mentions(e, "name: expected a non-empty string")) << joined(e);
  EXPECT_TRUE(mentions(e, "nmae: unknown field (known: ")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "count": "3"})j"));
  EXPECT_EQ(e, std::vector<std::string>{"count: expected an integer, got a string"});
  e = errors(kSchema, json::parse(R"j({"name": "n", "count": 2.5})j"));
  EXPECT_TRUE(mentions(e, "count: expected an integer, got a number")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "count": 11, "scale": 0})j"));
  EXPECT_TRUE(mentions(e, "count: expected a number <= 10")) << joined(e);
  EXPECT_TRUE(mentions(e, "scale: expected a number > 0")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "tags": []})j"));
  EXPECT_TRUE(mentions(e, "tags: expected at least 1 element")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "tags": ["x", 7, "x"]})j"));
  EXPECT_TRUE(mentions(e, "tags[1]: expected a string, got an integer")) << joined(e);
  EXPECT_TRUE(mentions(e, "tags[2]: \"x\" is listed twice")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "mode": "y"})j"));
  EXPECT_TRUE(mentions(e, "mode: matches none of the allowed forms")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "colours": {"plate2": "#a0b0c0", "cup": "red"}})j"));
  EXPECT_TRUE(mentions(e, "colours.plate2: field name \"plate2\"")) << joined(e);
  EXPECT_TRUE(mentions(e, "colours.cup: \"red\" does not match the pattern")) << joined(e);
  e = errors(kSchema, json::parse(R"j({"name": "n", "fixed": 4})j"));
  EXPECT_TRUE(mentions(e, "fixed: expected 3")) << joined(e);
  e = errors(kSchema, json::parse(R"j([1])j"));
  EXPECT_EQ(e, std::vector<std::string>{"(top level): expected an object, got an array"});
}

TEST(JsonSchema, KeywordsItDoesNotImplementAreRefused) {
  for (const char* schema : {R"j({"type": "object", "if": {"required": ["a"]}, "then": {}})j",
                             R"j({"properties": {"a": {"format": "email"}}})j",
                             R"j({"$defs": {"x": {"dependentRequired": {}}}})j"}) {
    try {
      JsonSchema(json::parse(schema), "s.json");
      ADD_FAILURE() << "accepted " << schema;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is not supported"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.json"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(JsonSchema(json::parse(R"j({"$ref": "#/$defs/missing"})j"), "s.json"), InputError);
  EXPECT_THROW(JsonSchema(json::parse(R"j({"pattern": "("})j"), "s.json"), InputError);
  EXPECT_THROW(JsonSchema(json::parse(R"j({"type": "text"})j"), "s.json"), InputError);
}

}  // namespace
}  // namespace clips::util
