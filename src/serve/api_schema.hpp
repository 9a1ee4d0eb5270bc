#pragma once
// The server's OpenAPI document (data/schema/serve-api.openapi.json) names
// its choices' values once: every schema with "x-clips-choices": "ID" takes
// its "enum" from the engine's name table of that ID (engine/choices.hpp):
// the canonical names, and with "x-clips-aliases": true (a request field
// that reads the older spellings) the aliases too.
// Its engine options likewise: a schema with "x-clips-options": "engine"
// (a session's "inference" object) takes its properties from the engine's
// option table (engine/options.hpp): names, help, types, ranges (particles at
// most the server's kMaxSessionParticles) and choices, registered options too. So an option added to that
// table is in the CLI's flags, Python's keywords, the server's fields and
// this document.
// A test keeps the file equal to the filled file; with CLIPS_UPDATE_SCHEMA=1
// it writes the filled document back.
#include <nlohmann/json.hpp>

namespace clips::serve {

// Sets each "x-clips-choices" schema's enum from the catalogue; returns how
// many schemas it set. std::invalid_argument for an ID the catalogue lacks.
size_t fill_choice_enums(nlohmann::ordered_json& doc);
// Sets each "x-clips-options" schema's properties from the option table, then
// their choices' enums (fill_choice_enums); returns how many schemas it set.
// std::invalid_argument for an unknown table.
size_t fill_option_properties(nlohmann::ordered_json& doc);
// The document as this process serves it (GET /api/openapi.json): the shipped
// one (embedded at build time) filled from the running tables, so a policy or
// an option registered in the process is in it.
nlohmann::ordered_json served_api_document();

}  // namespace clips::serve
