// The first word of the command line when it is not a subcommand: `scatterlab help [NAME]`
// prints the help, and a typo gets the nearest name ("unknown subcommand 'chek'; did you mean
// 'check'?") instead of CLI11's generic complaint.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

namespace scatterlab {

// The exit code when argv's first word (the first argument that is not an option) is `help`
// or no subcommand of `app`; nothing when it is a subcommand (or there is none), for CLI11 to
// parse.
std::optional<int> handleSubcommandWord(CLI::App& app, int argc, char** argv);

}  // namespace scatterlab
