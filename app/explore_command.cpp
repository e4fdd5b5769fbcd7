#include "app/explore_command.h"

#include <filesystem>
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/explorer/explorer_page.h"
#include "app/lab/staged_directory.h"
#include "app/material_argument.h"
#include "app/option_values.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/registry/material_file.h"
#include "materials/registry/parameter_spec.h"
#include "materials/registry/spec_validation.h"
#include "validation/chi_square_images.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The material a MATERIAL argument gives, built once so that a bad description or an unreadable
// table is refused before anything is written.
ExplorerMaterial loadExplorerMaterial(const std::string& argument) {
  const json material = materialFromArgument(argument);
  const bool inline_ = isInlineMaterial(argument);
  try {
    makeFarFieldBsdf(material);
    const json completed = completeMaterial(material);
    const std::string name =
        inline_ ? completed.value("type", std::string("material")) : fs::path(argument).filename().string();
    return {"", name, material};
  } catch (const MaterialError& error) {
    if (inline_) throw;
    throw MaterialError("material \"" + argument + "\": " + error.what());
  }
}

// Ids for the page's address (index.html#ID): the name made file-system safe, numbered when taken.
void assignIds(std::vector<ExplorerMaterial>& materials) {
  std::set<std::string> used;
  for (ExplorerMaterial& m : materials) {
    std::string base = safeFileStem(m.name);
    if (base.empty()) base = "material";
    m.id = base;
    for (int copy = 2; !used.insert(m.id).second; ++copy) m.id = base + "-" + std::to_string(copy);
  }
}

}  // namespace

CLI::App* addExploreCommand(CLI::App& app, ExploreCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "explore",
      "Write the explorer: a static page (DIR/index.html, opened from the file system) that shows any model "
      "live, computed by scatterlab's own code compiled to WebAssembly: inputs from the parameter specs, the "
      "lobe, f cos over the hemisphere, the albedo curve and the sampler's draws over its pdf");
  command->add_option("material", options.materials,
                      "Materials to preload: inline JSON, JSON files, or measured table files (embedded)");
  command->add_option("--out", options.out, "Directory of the page, replaced whole when it is complete")
      ->type_name("DIR")
      ->required()
      ->check(outputDirectoryValidator());
  command->add_flag("--json", options.json, "Print what was written as JSON");
  return command;
}

int runExploreCommand(const ExploreCommandOptions& options) {
  std::vector<ExplorerMaterial> materials;
  for (const std::string& argument : options.materials) materials.push_back(loadExplorerMaterial(argument));
  assignIds(materials);
  // The page replaces DIR only when DIR is provably an earlier page (its manifest), and never
  // the directory of a material file it reads.
  std::vector<InputPath> inputs;
  for (const std::string& argument : options.materials)
    if (!isInlineMaterial(argument)) inputs.push_back({"material file", argument});
  StagedDirectory staged(options.out, ExplorerGenerator, "--out", inputs);
  const ExplorerWritten written = writeExplorer(staged.path(), materials);
  staged.commit();
  const fs::path index = staged.target() / "index.html";
  if (options.json) {
    json given = json::array();
    for (const ExplorerMaterial& m : materials)
      given.push_back({{"id", m.id}, {"name", m.name}, {"link", "index.html#" + m.id}});
    std::cout << json{{"index", index.string()}, {"materials", given}, {"written", written.toJson()}}.dump(2)
              << "\n";
  } else {
    std::cout << "explorer: " << materials.size() << " given materials, " << written.tables << " tables, "
              << (written.bytes + 500'000) / 1'000'000 << " MB\nopen " << index.string() << "\n";
  }
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
