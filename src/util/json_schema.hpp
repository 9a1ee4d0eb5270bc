#pragma once
// A compact JSON Schema (draft 2020-12) validator for exactly the keywords
// clips's own schemas use (data/schema/pack.schema.json); Debian 12 has no C++
// JSON Schema library. A schema that uses any other keyword is refused when
// it is loaded, so a schema can never be checked only in part.
//
// Keywords: type (a name or an array of names), enum, const, properties,
// required, additionalProperties (true, false or a schema), propertyNames,
// items (one schema for every element), minItems, maxItems, uniqueItems,
// minimum, maximum, exclusiveMinimum, exclusiveMaximum, minLength, maxLength,
// pattern (ECMAScript, unanchored as the standard says), oneOf, anyOf, $ref
// (local JSON pointers, "#/$defs/name"), $defs. Annotations ($schema, $id,
// $comment, title, description, default, examples) are read and ignored.
// "integer" is any number with no fractional part (1.0 is one), as the
// standard has it.
#include <nlohmann/json.hpp>
#include <regex>
#include <map>
#include <string>
#include <vector>

namespace clips::util {

struct SchemaError {
  std::string path;     // where in the document: "roles.turns", "cost_profiles[0].profiles[1]", "" the top
  std::string message;  // what is wrong, e.g. "expected one of: \"domain\", \"alternate\""
  // "<path>: <message>", with "(top level)" for the document itself.
  std::string str() const;
};

class JsonSchema {
 public:
  // Throws clips::InputError naming `source` and the keyword for a keyword
  // outside the list above, a $ref that resolves to nothing, or a bad pattern.
  JsonSchema(nlohmann::json schema, std::string source);
  static JsonSchema load(const std::string& path);

  // Every violation of the schema by `doc` (empty: valid), in document order.
  std::vector<SchemaError> validate(const nlohmann::json& doc) const;

 private:
  void check_schema(const nlohmann::json& s, const std::string& where);
  const nlohmann::json& resolve(const std::string& ref) const;
  void validate_at(const nlohmann::json& s, const nlohmann::json& v, const std::string& path,
                   std::vector<SchemaError>& out) const;

  nlohmann::json schema_;
  std::string source_;
  std::map<std::string, std::regex> patterns_;  // compiled once, when the schema is loaded
};

}  // namespace clips::util
