#pragma once
// Small hand-made worlds for the command tests.
#include <string>
#include <vector>

#include "commands/language_config.hpp"
#include "commands/salient.hpp"
#include "commands/term.hpp"

namespace clips::commands::testing {

// mDKG objects are named <type><n>: key2 -> key.
inline std::string dkg_type_of(const std::string& object) {
  return object.substr(0, object.find_first_of("0123456789"));
}

// VH fixtures vs items.
inline std::string vh_type_of(const std::string& object) {
  for (const char* fixture : {"table", "cabinet", "fridge"})
    if (object.rfind(fixture, 0) == 0) return "fixture";
  return "item";
}

inline std::vector<Term> terms(const std::string& text) { return parse_terms(text); }

// Salient actions of `plan` with qualifiers taken from `facts`.
inline std::vector<SalientAction> salient_of(const std::string& plan, const std::string& facts,
                                             const LanguageConfig& config) {
  return extract_salient(parse_terms(plan), config, qualifier_lookup_from_facts(parse_terms(facts), config));
}

}  // namespace clips::commands::testing
