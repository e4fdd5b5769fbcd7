#include "app/generate_table_command.h"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <tbb/parallel_for.h>

#include "app/exit_code.h"
#include "app/progress.h"
#include "app/staged_outputs.h"
#include "materials/bsdf/white_microfacet_albedo.h"
#include "materials/core/atomic_file.h"

namespace scatterlab {

namespace {

constexpr const char* WhiteAlbedoTableName = "white-microfacet-albedo";

// %.17g: the text reads back as exactly the double that was computed, so regenerating on the
// same machine gives the same file.
std::string formatDouble(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string formatArray(const char* name, const std::vector<double>& values) {
  std::string out = "const std::array<double, WhiteAlbedoGrid::NodeCount> " + std::string(name) + " = {\n";
  for (int i = 0; i < WhiteAlbedoGrid::AlphaNodes; ++i) {
    out += "    // alpha = " + formatDouble(WhiteAlbedoGrid::alphaNode(i)) + "\n";
    for (int j = 0; j < WhiteAlbedoGrid::CosNodes; ++j) {
      out +=
          (j % 4 == 0 ? "    " : " ") + formatDouble(values[size_t(i) * WhiteAlbedoGrid::CosNodes + j]) + ",";
      if (j % 4 == 3 || j + 1 == WhiteAlbedoGrid::CosNodes) out += "\n";
    }
  }
  return out + "};\n";
}

std::vector<double> computeWhiteAlbedoTable(MicrofacetType type, std::atomic<int>& done,
                                            ProgressLine& progress, const std::string& label) {
  std::vector<double> values(WhiteAlbedoGrid::NodeCount);
  const auto callback = progress.callback(label);
  // Nodes are independent and each is computed the same way on any thread: the table does
  // not depend on the thread count.
  tbb::parallel_for(0, WhiteAlbedoGrid::NodeCount, [&](int n) {
    values[size_t(n)] =
        computeWhiteAlbedoNode(type, n / WhiteAlbedoGrid::CosNodes, n % WhiteAlbedoGrid::CosNodes);
    const int count = ++done;
    if (callback) callback("", double(count) / (2.0 * WhiteAlbedoGrid::NodeCount));
  });
  return values;
}

}  // namespace

std::vector<std::string> generatedTableNames() { return {WhiteAlbedoTableName}; }

std::string whiteAlbedoTableSource(const std::vector<double>& ggx, const std::vector<double>& beckmann,
                                   const std::string& command) {
  std::string out =
      "// GENERATED FILE - do not edit. Regenerate with\n"
      "//   " +
      command +
      "\n"
      "// E(mu, alpha): directional albedo of single-scattering GGX and Beckmann reflection with\n"
      "// Fresnel = 1 and Smith height-correlated masking-shadowing, at the nodes of WhiteAlbedoGrid\n"
      "// (materials/bsdf/white_microfacet_albedo.h): " +
      std::to_string(WhiteAlbedoGrid::AlphaNodes) +
      " rows uniform in sqrt(alpha) from alpha = 0.001 to 1,\n"
      "// each of " +
      std::to_string(WhiteAlbedoGrid::CosNodes) +
      " values uniform in u, mu = c alpha t / (1 + c alpha - t), t = sin^4(pi u / 2), c = 4.\n"
      "// Each node is whiteMicrofacetAlbedo() at whiteAlbedoQuadrature(): adaptive Simpson over the\n"
      "// visible-normal sample square, tolerance 1e-7, absolute error below 1e-6; mu = 0 is the\n"
      "// grazing limit 1. tests/materials/bsdf/white_microfacet_albedo_test.cpp regenerates entries.\n"
      "#include \"materials/bsdf/white_microfacet_albedo.h\"\n\n"
      "namespace scatterlab {\n\n"
      "// The grid these values belong to; changing it means regenerating this file.\n"
      "static_assert(WhiteAlbedoGrid::AlphaNodes == " +
      std::to_string(WhiteAlbedoGrid::AlphaNodes) +
      " && WhiteAlbedoGrid::CosNodes == " + std::to_string(WhiteAlbedoGrid::CosNodes) +
      " && WhiteAlbedoGrid::AlphaMin == " + formatDouble(WhiteAlbedoGrid::AlphaMin) +
      " && WhiteAlbedoGrid::MoebiusScale == " + formatDouble(WhiteAlbedoGrid::MoebiusScale) + ");\n\n";
  out += formatArray("GgxWhiteAlbedoTable", ggx) + "\n" + formatArray("BeckmannWhiteAlbedoTable", beckmann);
  return out + "\n}  // namespace scatterlab\n";
}

CLI::App* addGenerateTableCommand(CLI::App& app, GenerateTableOptions& options) {
  CLI::App* command = app.add_subcommand(
      "generate-table",
      "Developer command: compute a precomputed table of the models and write it as C++ source");
  command->group("");  // hidden from `scatterlab --help`
  command->add_option("table", options.table, "Which table")
      ->required()
      ->check(CLI::IsMember(generatedTableNames()));
  command->add_option("--out,--output", options.output, "The C++ source file to write")->required();
  return command;
}

int runGenerateTableCommand(const GenerateTableOptions& options) {
  const std::filesystem::path output(options.output);
  StagedOutputs outputs;
  outputs.addFile("--out", output, "materials/bsdf/tables/white_microfacet_albedo_table.cpp");
  outputs.prepare();
  ProgressLine progress;
  std::atomic<int> done{0};
  const std::vector<double> ggx =
      computeWhiteAlbedoTable(MicrofacetType::Ggx, done, progress, "GGX and Beckmann");
  const std::vector<double> beckmann =
      computeWhiteAlbedoTable(MicrofacetType::Beckmann, done, progress, "GGX and Beckmann");
  progress.clear();
  const std::string command = "scatterlab generate-table " + options.table + " --out " + options.output;
  writeTextFileAtomically(outputs.staged(output), whiteAlbedoTableSource(ggx, beckmann, command));
  outputs.commit();
  std::cerr << "wrote " << output.string() << "\n";
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
