// Validators for the values of command-line options. Each rejects a bad value with one
// message naming the value and what is allowed; CLI11 prefixes the option's name, so the
// user reads e.g. `--grid: "64" is not a grid; allowed: ...`.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "materials/registry/parameter_spec.h"

namespace scatterlab {

// A finite real number inside `range`; `what` names it in messages ("degrees", "a number").
CLI::Validator numberIn(const ValueRange& range, const std::string& what = "a number");

// An integer in [lo, hi]; "1e6" is accepted and rewritten as "1000000". Use with
// CLI::Option::transform so that the rewritten text is what CLI11 converts.
CLI::Validator integerIn(uint64_t lo, uint64_t hi = std::numeric_limits<uint64_t>::max());

// --seed and --threads of a command whose random `work` ("walk") gives the same numbers for a
// seed on any number of threads (0: all cores).
void addSeedAndThreadOptions(CLI::App* command, uint64_t& seed, int& threads, const std::string& work);

// The chi-square grid "COSxPHI": cos(theta) cells x phi cells.
struct GridSize {
  int cosThetaCells = 0;
  int phiCells = 0;
};
inline constexpr int MinGridCells = 2;
inline constexpr int MaxGridCells = 4096;
// The grid `text` describes, or nothing unless each side is in [MinGridCells, MaxGridCells].
std::optional<GridSize> parseGrid(const std::string& text);
CLI::Validator gridValidator();

// A directory that may not exist yet (it is created once every input is valid), but is not
// an existing file.
CLI::Validator outputDirectoryValidator();

// One of `names`; `what` names the kind in messages ("a metric").
CLI::Validator choiceOf(const std::vector<std::string>& names, const std::string& what);

// An output file to write: not empty, not a directory, in a directory that exists; throws
// InputError naming `option` otherwise. `example` ends the message ("gold.binary").
void checkOutputFile(const std::string& option, const std::string& path, const std::string& example);

}  // namespace scatterlab
