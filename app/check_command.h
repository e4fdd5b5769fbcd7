// `scatterlab check`: the statistical test kit (VALIDATION.md sections 1-4) on materials given
// as inline JSON or files, or on the built-in showcase. Prints each completed material and
// the verdict table, or one JSON document with --json.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "validation/bsdf_check.h"

namespace scatterlab {

struct CheckCommandOptions {
  std::vector<std::string> materials;  // inline JSON or file paths; none: the showcase
  BsdfCheckOptions kit;
  bool negativeControls = false;
  bool json = false;
};

// Declares the subcommand on `app`, its options bound to `options`.
CLI::App* addCheckCommand(CLI::App& app, CheckCommandOptions& options);

// Validates every material and option before any work or output file, then runs the kit.
// Returns the exit code: 0 when every row passes, 1 otherwise. Bad input throws
// MaterialError or InputError.
int runCheckCommand(const CheckCommandOptions& options);

}  // namespace scatterlab
