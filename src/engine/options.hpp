#pragma once
// The one table of particle option names (clips::ParticleOptions): `clips
// infer`, `clips bench` and `clips serve` build their flags from it (the name
// with '-' for '_': --ess-threshold), Python reads its keywords through it
// and the server its JSON fields, so a name, a range and an error message
// exist once. Every value is parsed from text (a flag's text, Python's str()
// of an int or repr() of a float, a JSON number's dump), so a bad value gives
// the same message from every front end:
//   "ess_threshold must be a number from 0 to 1, got 2.0"
#include <optional>
#include <string>
#include <vector>

#include "clips/types.hpp"

namespace clips::inference {
struct InferenceOptions;
}

namespace clips::engine {

struct ParticleOption {
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
};

// The options, as they stand (a choice registered at run time is listed).
std::vector<ParticleOption> particle_option_table();
// "--ess-threshold".
std::string cli_flag(const ParticleOption& option);
// The option's value in `o`, as text ("0.5", "evidence").
std::string particle_option_text(const ParticleOptions& o, const std::string& name);
// Parses `text` into the option `name` of `o`. InputError "<name> must be
// <takes>, got <text>" for a bad value, "unknown particle option" for a name
// not in the table.
void set_particle_option(ParticleOptions& o, const std::string& name, const std::string& text);
// The one validation: every field of `o` as set_particle_option checks it
// (InputError naming the first bad one).
void check_particle_options(const ParticleOptions& o);
// The one conversion into the belief's options, checked first.
void apply_particle_options(const ParticleOptions& o, inference::InferenceOptions& io);

}  // namespace clips::engine
