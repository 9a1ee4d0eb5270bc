#pragma once
// The one table of the engine's options (clips::ParticleOptions: the
// particle settings, and options a library user registers at run time for
// a policy of their own, clips::register_option): `clips infer`, `clips
// bench` and `clips serve` build their flags from it (the name with '-' for
// '_': --ess-threshold), the server its JSON fields and its OpenAPI document
// the fields' types, and Python's keywords are the session table below,
// which holds it; so a name, a range and an error message exist once. Every
// value is parsed from text (a flag's text, Python's str() of an int or
// repr() of a float, a JSON number's dump), so a bad value gives the same
// message from every front end:
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
  // Text and List: the session table's own rows only (a URL, PDDL goals).
  enum class Kind { Integer, Real, Choice, Text, List };
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
// Adds `option` (kind Integer, Real or Choice; name, help, default and range
// or choices filled; `takes` is filled here) to the table. InputError for a
// name that is not lower-case letters, digits and '_', one the session table
// or Python's openers already use (reserved_option_names), or a default out
// of range.
void register_option(EngineOption option);
// Takes back an option register_option added; InputError for another name.
void unregister_option(const std::string& name);
// Names no registered option may take besides the session table's: the
// arguments of Python's openers. A CLI command with a flag of a registered
// option's name keeps its own (add_particle_options).
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
// The session's options (clips::SessionOptions) as Python's openers take them
// (the keywords of open_dataset and open_domain): the session's own rows
// (method, assistance, lm, lm_base_url, lm_model, lm_timeout, goals,
// cost_profiles, max_nodes, threads, assist_max_nodes, assist_rule, qa_floor,
// search_seconds), then option_table()'s, then assistant_turns. The server
// and the CLI take only option_table()'s: the others are their own limits
// and flags (a server's threads and node budgets, its language model).
std::vector<EngineOption> session_option_table();
// Parses `text` (a List: `items`) into the session option `name` of `o`;
// InputError as set_option's, the name tables' "unknown method ..." for a
// choice, "unknown option" for a name of neither table.
void set_session_option(SessionOptions& o, const std::string& name, const std::string& text);
void set_session_option(SessionOptions& o, const std::string& name, const std::vector<std::string>& items);
// The option's value in `o` as text (a List: its items joined by ", ").
std::string session_option_text(const SessionOptions& o, const std::string& name);
// docs/library.md's table of the session options (name, what it takes, its
// default, its help), one row per session_option_table() row.
std::string session_options_markdown();
// The one validation: every field of `o` as set_option checks it
// (InputError naming the first bad one), and no value for an option that is
// not registered.
void check_options(const ParticleOptions& o);
// The one conversion into the belief's options, checked first.
void apply_particle_options(const ParticleOptions& o, inference::InferenceOptions& io);

}  // namespace clips::engine
