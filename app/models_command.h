// `scatterlab models`: every material model with its parameters, kinds, ranges, defaults,
// description and citation, as a table, as JSON or as Markdown (docs/models.md).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct ModelsCommandOptions {
  bool json = false;
  bool markdown = false;
};

// Declares the subcommand on `app`, its options bound to `options`.
CLI::App* addModelsCommand(CLI::App& app, ModelsCommandOptions& options);
int runModelsCommand(const ModelsCommandOptions& options);

// The readable catalog that `scatterlab models` prints.
std::string formatModelCatalog();
// The same catalogue as a Markdown page: docs/models.md is this text, and a test keeps them equal.
std::string formatModelCatalogMarkdown();

}  // namespace scatterlab
