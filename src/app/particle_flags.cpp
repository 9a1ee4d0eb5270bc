#include "app/particle_flags.hpp"

#include <memory>
#include <string>

#include "engine/options.hpp"
#include "util/error.hpp"

namespace clips::app {

void add_particle_options(CLI::App* cmd, ParticleFlags& f, const std::set<std::string>& skip) {
  for (const auto& option : engine::option_table()) {
    if (skip.count(option.name)) continue;
    // A registered option named as one of the command's own flags is left
    // to the command (the binary registers none; a program embedding the CLI might).
    if (option.registered && cmd->get_option_no_throw(engine::cli_flag(option))) continue;
    const std::string name = option.name;
    // The flag's text goes through the table's parser, which checks it and
    // gives the message every front end gives for a bad value.
    auto* o = cmd->add_option_function<std::string>(
        engine::cli_flag(option), [&f, name](const std::string& text) { engine::set_option(f, name, text); },
        option.kind == engine::EngineOption::Kind::Choice ? option.help : option.help + " [" + option.takes + "]");
    o->check(CLI::Validator(
        [name](std::string& text) {
          ParticleOptions scratch;
          try {
            engine::set_option(scratch, name, text);
            return std::string();
          } catch (const InputError& e) {
            return std::string(e.what());
          }
        },
        ""));
    std::string type = option.kind == engine::EngineOption::Kind::Real ? "X" : "N";
    if (option.kind == engine::EngineOption::Kind::Choice) {
      type.clear();
      for (const auto& c : option.choices) type += (type.empty() ? "" : "|") + c;
    }
    o->type_name(type);
  }
}

void apply_particle_flags(const ParticleFlags& flags, inference::InferenceOptions& options) {
  engine::apply_particle_options(flags, options);
}

void apply_particle_flags(const ParticleFlags& flags, SessionOptions& options) {
  engine::check_options(flags);
  static_cast<ParticleOptions&>(options) = flags;
}

}  // namespace clips::app
