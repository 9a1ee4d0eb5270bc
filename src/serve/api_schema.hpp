#pragma once
// The server's OpenAPI document (data/schema/serve-api.openapi.json) names
// its choices' values once: every schema with "x-clips-choices": "ID" takes
// its "enum" from the engine's name table of that ID (engine/choices.hpp):
// the canonical names, and with "x-clips-aliases": true (a request field
// that reads the older spellings) the aliases too.
// A test keeps the file equal to fill_choice_enums(file); with
// CLIPS_UPDATE_SCHEMA=1 it writes the filled document back.
#include <nlohmann/json.hpp>

namespace clips::serve {

// Sets each "x-clips-choices" schema's enum from the catalogue; returns how
// many schemas it set. std::invalid_argument for an ID the catalogue lacks.
size_t fill_choice_enums(nlohmann::ordered_json& doc);

}  // namespace clips::serve
