#pragma once
// A flag that takes one name of a name table (util/choices.hpp): its --help
// lists the names and what each does, and CLI11 refuses any other spelling
// with the list. Header-only, so a test can build a flag the way the
// subcommands do and see a name registered at run time in its help.
#include <CLI/CLI.hpp>
#include <string>

#include "util/choices.hpp"

namespace clips::app {

// `lead` says what the flag chooses ("Assistance policy of the inference
// methods"); the table's names and help follow it. With `aliases`, the older
// spellings are taken too.
template <typename V>
CLI::Option* add_choice_option(CLI::App* cmd, const std::string& flag, std::string& value,
                               const util::Choices<V>& table, const std::string& lead, bool aliases = false) {
  return cmd->add_option(flag, value, lead + ": " + table.help_text())
      ->check(CLI::IsMember(aliases ? table.spellings() : table.names()));
}

}  // namespace clips::app
