// `scatterlab explore [MATERIAL...] --out DIR`: writes the explorer (app/explorer/explorer_page.h,
// docs/explorer.md), a static page that shows any registry model live in a browser opened from
// the file system: inputs from the parameter specs, the lobe, a heat map of f cos, the albedo
// curve and the model's own samples over its pdf, all computed by scatterlab's model code
// compiled to WebAssembly. The MATERIALs given (inline JSON, JSON files, measured tables) are
// preloaded, their tables embedded. DIR is replaced whole or not at all (staged_directory.h).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct ExploreCommandOptions {
  std::vector<std::string> materials;
  std::string out;
  bool json = false;
};

CLI::App* addExploreCommand(CLI::App& app, ExploreCommandOptions& options);

// Returns 0; bad input throws MaterialError or InputError (exit 2) before anything is written.
int runExploreCommand(const ExploreCommandOptions& options);

}  // namespace scatterlab
