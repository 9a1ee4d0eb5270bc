#include "serve/api_schema.hpp"

#include <stdexcept>

#include "engine/choices.hpp"

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

}  // namespace

size_t fill_choice_enums(nlohmann::ordered_json& doc) { return fill(doc, engine::choice_catalogue()); }

}  // namespace clips::serve
