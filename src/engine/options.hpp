#pragma once
// The one table of the engine's options (clips::ParticleOptions: the
// particle settings, and options a library user registers at run time for
// a policy of their own, clips::register_option): `clips infer`, `clips
// bench` and `clips serve` build their flags from it (the name with '-' for
// '_': --ess-threshold), Python reads its keywords through it, the server
// its JSON fields and its OpenAPI document the fields' types, so a name, a
// range and an error message exist once. Every value is parsed from text (a flag's text, Python's str()
// of an int or repr() of a float, a JSON number's dump), so a bad value gives
// the same message from every front end:
//   "ess_threshold must be a number from 0 to 1, got 2.0"
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "clips/types.hpp"

namespace clips::inference {
struct InferenceOptions;
}

namespace clips::engine {

struct EngineOption {
  enum class Kind { Integer, Real, Choice };
  std::string name;   // the field, Python keyword and JSON name: "ess_threshold"
  Kind kind;
  std::string takes;  // what it takes, as errors say it: "a number from 0 to 1"
  std::string brief;  // a few words, for Python's docstrings
  std::string help;   // what --help says
  std::vector<std::string> choices;  // Kind::Choice
  // Kind::Integer and Kind::Real: the range, for schemas (an integer bound
  // beyond 2^53, which a JSON number does not hold exactly, is left out).
  std::optional<double> minimum, maximum;
  // Registered at run time (register_option): its value lives in
  // ParticleOptions::registered_options, and no name table of the choice
  // catalogue lists its choices.
  bool registered = false;
  std::string default_text;  // registered options: the value when unset
};

// The options, as they stand (a choice or an option registered at run time
// is listed).
std::vector<EngineOption> option_table();
// Adds `option` (registered set, kind, name, help, default and range or
// choices filled; `takes` is filled here) to the table. InputError for a name
// that is not lower-case letters, digits and '_', one the table or a front
// end already uses (reserved_option_names), or a default out of range.
void register_option(EngineOption option);
// Takes back an option register_option added; InputError for another name.
void unregister_option(const std::string& name);
// Names no registered option may take besides the table's: Python's own
// session keywords and openers' arguments, the session's other fields
// (method, assistance, lm, goals, threads, ...). A CLI command with a flag
// of a registered option's name keeps its own (add_particle_options).
const std::vector<std::string>& reserved_option_names();
// Every registered option's value in `o` (its default when unset), by name:
// what a registered policy sees (clips::PolicyView::options).
std::map<std::string, std::string> registered_option_values(const ParticleOptions& o);
// "--ess-threshold".
std::string cli_flag(const EngineOption& option);
// The option's value in `o`, as text ("0.5", "evidence").
std::string option_text(const ParticleOptions& o, const std::string& name);
// Parses `text` into the option `name` of `o`. InputError "<name> must be
// <takes>, got <text>" for a bad value, "unknown option" for a name
// not in the table.
void set_option(ParticleOptions& o, const std::string& name, const std::string& text);
// The one validation: every field of `o` as set_option checks it
// (InputError naming the first bad one), and no value for an option that is
// not registered.
void check_options(const ParticleOptions& o);
// The one conversion into the belief's options, checked first.
void apply_particle_options(const ParticleOptions& o, inference::InferenceOptions& io);

}  // namespace clips::engine
