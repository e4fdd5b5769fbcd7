// `scatterlab lab [MATERIAL ...] [--out DIR] [--quick]`: one static HTML report per run, with
// every material's verdict, plots, fits and renders. With no MATERIAL it reports on
// the built-in showcase (lab_showcase.h). DIR is replaced whole or not at all
// (staged_directory.h); the report opens from the file system, with no server.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct LabCommandOptions {
  std::vector<std::string> materials;  // inline JSON, JSON files or .binary MERL files; none: the showcase
  std::string out = "lab-report";
  bool quick = false;
  uint64_t seed = 1;
  std::vector<std::string>
      environments;  // equirectangular EXR maps for the renders; none: two of data/envmaps
  bool json = false;
};

CLI::App* addLabCommand(CLI::App& app, LabCommandOptions& options);

// Validates every material and --out before any work. Returns 0 when every material passes
// its checks, 1 when one fails (the report is written either way); bad input throws
// MaterialError or InputError (exit 2) and leaves DIR as it was.
int runLabCommand(const LabCommandOptions& options);

}  // namespace scatterlab
