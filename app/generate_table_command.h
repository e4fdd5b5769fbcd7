// `scatterlab generate-table` (a developer command, hidden from the help listing): computes a
// table that the models ship precomputed and writes it as a C++ source file, which is
// committed. The file's header comment names the command that produced it; tests regenerate
// some of its entries and compare.
//
// Tables: "white-microfacet-albedo", E(mu, alpha) of single-scattering GGX and Beckmann
// reflection with Fresnel = 1 (materials/bsdf/white_microfacet_albedo.h), for Kulla-Conty
// multiple-scattering compensation.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct GenerateTableOptions {
  std::string table;
  std::string output;
};

// The names of the tables the command generates.
std::vector<std::string> generatedTableNames();

CLI::App* addGenerateTableCommand(CLI::App& app, GenerateTableOptions& options);

// Computes the table and writes the source file atomically. Returns the exit code (0); bad
// input throws InputError.
int runGenerateTableCommand(const GenerateTableOptions& options);

// The source text of the white-microfacet-albedo table from its node values (GGX then
// Beckmann, each WhiteAlbedoGrid::NodeCount, alpha-major); `command` is quoted in the header.
std::string whiteAlbedoTableSource(const std::vector<double>& ggx, const std::vector<double>& beckmann,
                                   const std::string& command);

}  // namespace scatterlab
