// `scatterlab models`: every material model with its parameters, kinds, ranges, defaults,
// description and citation, as a table or as JSON.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct ModelsCommandOptions {
  bool json = false;
};

// Declares the subcommand on `app`, its options bound to `options`.
CLI::App* addModelsCommand(CLI::App& app, ModelsCommandOptions& options);
int runModelsCommand(const ModelsCommandOptions& options);

// The readable catalog that `scatterlab models` prints.
std::string formatModelCatalog();

}  // namespace scatterlab
