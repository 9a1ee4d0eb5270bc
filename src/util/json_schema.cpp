#include "util/json_schema.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "util/error.hpp"

namespace clips::util {

namespace {

using nlohmann::json;

const std::set<std::string>& annotations() {
  static const std::set<std::string> a = {"$schema", "$id", "$comment", "title", "description", "default", "examples"};
  return a;
}

const std::set<std::string>& keywords() {
  static const std::set<std::string> k = {
      "type",       "enum",          "const",    "properties", "required",         "additionalProperties",
      "propertyNames", "items",      "minItems", "maxItems",   "uniqueItems",      "minimum",
      "maximum",    "exclusiveMinimum", "exclusiveMaximum", "minLength", "maxLength", "pattern",
      "oneOf",      "anyOf",         "$ref",     "$defs"};
  return k;
}

// The JSON type names a value has ("integer" values are numbers too).
bool has_type(const json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  if (type == "number") return v.is_number();
  if (type == "integer") {
    if (v.is_number_integer()) return true;
    if (!v.is_number_float()) return false;
    const double x = v.get<double>();
    return std::isfinite(x) && x == std::floor(x);
  }
  return false;
}

std::string type_of(const json& v) {
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_null()) return "null";
  if (v.is_number_integer() || has_type(v, "integer")) return "an integer";
  return "a number";
}

std::string article(const std::string& type) {
  if (type == "null") return "null";
  return (type == "object" || type == "array" || type == "integer" ? "an " : "a ") + type;
}

std::string join_path(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// A short printed value for messages.
std::string shown(const json& v) {
  std::string s = v.dump();
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

std::string number_text(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

}  // namespace

std::string SchemaError::str() const { return (path.empty() ? "(top level)" : path) + ": " + message; }

JsonSchema::JsonSchema(json schema, std::string source) : schema_(std::move(schema)), source_(std::move(source)) {
  check_schema(schema_, "#");
}

JsonSchema JsonSchema::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot read the schema file");
  std::ostringstream ss;
  ss << in.rdbuf();
  json doc;
  try {
    doc = json::parse(ss.str());
  } catch (const json::exception& e) {
    throw InputError(SourceLoc{path, 0, 0}, std::string("invalid JSON: ") + e.what());
  }
  return JsonSchema(std::move(doc), path);
}

void JsonSchema::check_schema(const json& s, const std::string& where) {
  auto bad = [&](const std::string& why) { throw InputError(SourceLoc{source_, 0, 0}, where + ": " + why); };
  if (s.is_boolean()) return;
  if (!s.is_object()) bad("a schema must be an object or a boolean");
  for (const auto& [key, value] : s.items()) {
    if (annotations().contains(key)) continue;
    if (!keywords().contains(key))
      bad("keyword '" + key + "' is not supported by clips's schema validator (src/util/json_schema.hpp lists those it is)");
    const std::string at = where + "/" + key;
    if (key == "properties" || key == "$defs") {
      if (!value.is_object()) bad(key + " must be an object");
      for (const auto& [name, sub] : value.items()) check_schema(sub, at + "/" + name);
    } else if (key == "additionalProperties" || key == "items" || key == "propertyNames") {
      check_schema(value, at);
    } else if (key == "oneOf" || key == "anyOf") {
      if (!value.is_array() || value.empty()) bad(key + " must be a non-empty array of schemas");
      for (size_t i = 0; i < value.size(); ++i) check_schema(value[i], at + "/" + std::to_string(i));
    } else if (key == "$ref") {
      if (!value.is_string()) bad("$ref must be a string");
      resolve(value.get<std::string>());
    } else if (key == "pattern") {
      if (!value.is_string()) bad("pattern must be a string");
      try {
        patterns_.emplace(value.get<std::string>(), std::regex(value.get<std::string>(), std::regex::ECMAScript));
      } catch (const std::regex_error& e) {
        bad("pattern " + shown(value) + " is not a regular expression (" + e.what() + ")");
      }
    } else if (key == "type") {
      const json types = value.is_array() ? value : json::array({value});
      for (const auto& t : types)
        if (!t.is_string() || !std::set<std::string>{"object", "array", "string", "boolean", "null", "number", "integer"}
                                   .contains(t.get<std::string>()))
          bad("unknown type " + shown(t));
    } else if (key == "required") {
      if (!value.is_array()) bad("required must be an array of names");
    } else if (key == "enum") {
      if (!value.is_array() || value.empty()) bad("enum must be a non-empty array");
    } else if (key != "const" && key != "uniqueItems" && !value.is_number()) {
      bad(key + " must be a number");
    }
  }
}

const json& JsonSchema::resolve(const std::string& ref) const {
  if (ref.rfind("#", 0) != 0)
    throw InputError(SourceLoc{source_, 0, 0}, "$ref " + ref + ": only references inside the schema (#/...) are supported");
  try {
    return schema_.at(json::json_pointer(ref.substr(1)));
  } catch (const json::exception&) {
    throw InputError(SourceLoc{source_, 0, 0}, "$ref " + ref + " resolves to nothing");
  }
}

std::vector<SchemaError> JsonSchema::validate(const json& doc) const {
  std::vector<SchemaError> out;
  validate_at(schema_, doc, "", out);
  return out;
}

void JsonSchema::validate_at(const json& s, const json& v, const std::string& path, std::vector<SchemaError>& out) const {
  if (s.is_boolean()) {
    if (!s.get<bool>()) out.push_back({path, "not allowed here"});
    return;
  }
  auto error = [&](const std::string& message) { out.push_back({path, message}); };
  if (auto r = s.find("$ref"); r != s.end()) validate_at(resolve(r->get<std::string>()), v, path, out);

  if (auto t = s.find("type"); t != s.end()) {
    const json types = t->is_array() ? *t : json::array({*t});
    bool ok = false;
    std::string names;
    for (const auto& name : types) {
      ok = ok || has_type(v, name.get<std::string>());
      names += (names.empty() ? "" : " or ") + article(name.get<std::string>());
    }
    if (!ok) {
      error("expected " + names + ", got " + type_of(v));
      return;  // the other keywords would only repeat it
    }
  }
  if (auto e = s.find("enum"); e != s.end()) {
    bool ok = false;
    std::string allowed;
    for (const auto& x : *e) {
      ok = ok || x == v;
      allowed += (allowed.empty() ? "" : ", ") + x.dump();
    }
    if (!ok) error("expected one of: " + allowed + ", got " + shown(v));
  }
  if (auto c = s.find("const"); c != s.end() && *c != v) error("expected " + c->dump() + ", got " + shown(v));

  if (v.is_object()) {
    const json* props = s.contains("properties") ? &s["properties"] : nullptr;
    if (auto req = s.find("required"); req != s.end())
      for (const auto& name : *req)
        if (!v.contains(name.get<std::string>())) out.push_back({join_path(path, name.get<std::string>()), "missing (required)"});
    const auto names = s.find("propertyNames");
    const auto extra = s.find("additionalProperties");
    for (const auto& [key, value] : v.items()) {
      const std::string at = join_path(path, key);
      if (names != s.end()) {
        std::vector<SchemaError> bad;
        validate_at(*names, json(key), at, bad);
        for (auto& b : bad) out.push_back({at, "field name " + json(key).dump() + ": " + b.message});
      }
      if (props && props->contains(key)) {
        validate_at((*props)[key], value, at, out);
      } else if (extra != s.end()) {
        if (extra->is_boolean() && !extra->get<bool>()) {
          std::string known;
          if (props)
            for (const auto& [k, unused] : props->items())
              if (k != "comment" && k != "$schema") known += (known.empty() ? "" : ", ") + k;
          out.push_back({at, "unknown field" + (known.empty() ? std::string() : " (known: " + known + ")")});
        } else {
          validate_at(*extra, value, at, out);
        }
      }
    }
  }
  if (v.is_array()) {
    if (auto m = s.find("minItems"); m != s.end() && v.size() < m->get<size_t>())
      error("expected at least " + std::to_string(m->get<size_t>()) + " element" + (m->get<size_t>() == 1 ? "" : "s") +
            ", got " + std::to_string(v.size()));
    if (auto m = s.find("maxItems"); m != s.end() && v.size() > m->get<size_t>())
      error("expected at most " + std::to_string(m->get<size_t>()) + " elements, got " + std::to_string(v.size()));
    if (auto u = s.find("uniqueItems"); u != s.end() && u->get<bool>())
      for (size_t i = 0; i < v.size(); ++i)
        for (size_t j = 0; j < i; ++j)
          if (v[i] == v[j]) out.push_back({path + "[" + std::to_string(i) + "]", shown(v[i]) + " is listed twice"});
    if (auto items = s.find("items"); items != s.end())
      for (size_t i = 0; i < v.size(); ++i) validate_at(*items, v[i], path + "[" + std::to_string(i) + "]", out);
  }
  if (v.is_number()) {
    const double x = v.get<double>();
    if (auto m = s.find("minimum"); m != s.end() && !(x >= m->get<double>()))
      error("expected a number >= " + number_text(m->get<double>()) + ", got " + shown(v));
    if (auto m = s.find("maximum"); m != s.end() && !(x <= m->get<double>()))
      error("expected a number <= " + number_text(m->get<double>()) + ", got " + shown(v));
    if (auto m = s.find("exclusiveMinimum"); m != s.end() && !(x > m->get<double>()))
      error("expected a number > " + number_text(m->get<double>()) + ", got " + shown(v));
    if (auto m = s.find("exclusiveMaximum"); m != s.end() && !(x < m->get<double>()))
      error("expected a number < " + number_text(m->get<double>()) + ", got " + shown(v));
  }
  if (v.is_string()) {
    const std::string& text = v.get_ref<const std::string&>();
    // Lengths count code points, not bytes.
    size_t length = 0;
    for (unsigned char c : text) length += (c & 0xC0) != 0x80;
    if (auto m = s.find("minLength"); m != s.end() && length < m->get<size_t>())
      error(m->get<size_t>() == 1 ? "expected a non-empty string"
                                  : "expected at least " + std::to_string(m->get<size_t>()) + " characters");
    if (auto m = s.find("maxLength"); m != s.end() && length > m->get<size_t>())
      error("expected at most " + std::to_string(m->get<size_t>()) + " characters");
    if (auto p = s.find("pattern"); p != s.end() && !std::regex_search(text, patterns_.at(p->get<std::string>())))
      error(shown(v) + " does not match the pattern " + p->get<std::string>());
  }
  for (const char* key : {"oneOf", "anyOf"}) {
    auto alts = s.find(key);
    if (alts == s.end()) continue;
    int matched = 0;
    std::string why;
    for (const auto& alt : *alts) {
      std::vector<SchemaError> sub;
      validate_at(alt, v, path, sub);
      if (sub.empty()) ++matched;
      else why += (why.empty() ? "" : "; or ") + sub.front().message;
    }
    if (matched == 0) error("matches none of the allowed forms: " + why);
    else if (matched > 1 && std::string(key) == "oneOf") error("matches more than one of the forms oneOf allows");
  }
}

}  // namespace clips::util
