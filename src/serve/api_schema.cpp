#include "serve/api_schema.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "engine/choices.hpp"
#include "engine/options.hpp"
#include "serve/service.hpp"

namespace clips::serve {

namespace {

size_t fill(nlohmann::ordered_json& node, const util::ChoiceCatalogue& catalogue) {
  size_t n = 0;
  if (node.is_object()) {
    if (node.contains("x-clips-choices")) {
      const std::string id = node["x-clips-choices"].get<std::string>();
      const util::ChoiceKind* kind = nullptr;
      for (const auto& [name, k] : catalogue)
        if (name == id) kind = &k;
      if (!kind) throw std::invalid_argument("x-clips-choices: no name table '" + id + "'");
      // A request field that reads the older spellings too says so.
      const bool aliases = node.value("x-clips-aliases", false);
      node["enum"] = aliases ? kind->spellings() : kind->names();
      ++n;
    }
    for (auto& [key, value] : node.items()) n += fill(value, catalogue);
  } else if (node.is_array()) {
    for (auto& value : node) n += fill(value, catalogue);
  }
  return n;
}

nlohmann::ordered_json particle_properties() {
  nlohmann::ordered_json props = nlohmann::ordered_json::object();
  using Kind = engine::EngineOption::Kind;
  for (const auto& o : engine::option_table()) {
    nlohmann::ordered_json p;
    if (o.kind == Kind::Choice) {
      p["type"] = "string";
      p["enum"] = o.choices;
      if (!o.registered) p["x-clips-choices"] = o.name;  // the catalogue's kind of the same name
    } else {
      p["type"] = o.kind == Kind::Integer ? "integer" : "number";
      if (o.minimum) p["minimum"] = o.kind == Kind::Integer ? nlohmann::ordered_json(static_cast<long long>(*o.minimum))
                                                            : nlohmann::ordered_json(*o.minimum);
      std::optional<double> hi = o.maximum;
      if (o.name == "particles") hi = std::min(hi.value_or(kMaxSessionParticles), double{kMaxSessionParticles});
      if (hi) p["maximum"] = o.kind == Kind::Integer ? nlohmann::ordered_json(static_cast<long long>(*hi))
                                                    : nlohmann::ordered_json(*hi);
    }
    p["description"] = o.help;
    props[o.name] = p;
  }
  return props;
}

size_t fill_options(nlohmann::ordered_json& node) {
  size_t n = 0;
  if (node.is_object()) {
    if (node.contains("x-clips-options")) {
      const std::string id = node["x-clips-options"].get<std::string>();
      if (id != "engine") throw std::invalid_argument("x-clips-options: no option table '" + id + "'");
      node["properties"] = particle_properties();
      ++n;
    }
    for (auto& [key, value] : node.items()) n += fill_options(value);
  } else if (node.is_array()) {
    for (auto& value : node) n += fill_options(value);
  }
  return n;
}

}  // namespace

size_t fill_choice_enums(nlohmann::ordered_json& doc) { return fill(doc, engine::choice_catalogue()); }

size_t fill_option_properties(nlohmann::ordered_json& doc) {
  const size_t n = fill_options(doc);
  fill_choice_enums(doc);
  return n;
}

nlohmann::ordered_json served_api_document() {
  const auto& docs = api_documents();
  const auto it = docs.find("/serve-api.openapi.json");
  if (it == docs.end()) throw std::logic_error("the OpenAPI document is not embedded");
  auto doc = nlohmann::ordered_json::parse(it->second.body);
  fill_option_properties(doc);
  return doc;
}

}  // namespace clips::serve
