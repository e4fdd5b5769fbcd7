#include "app/models_command.h"

#include <algorithm>
#include <array>
#include <iostream>
#include <vector>

#include "app/exit_code.h"
#include "materials/registry/model_list.h"

namespace scatterlab {

namespace {

constexpr size_t ColumnCount = 5;
using TableRow = std::array<std::string, ColumnCount>;

// Left-aligned columns, two spaces apart, indented under the model's heading.
std::string formatColumns(const std::vector<TableRow>& rows) {
  std::array<size_t, ColumnCount> width{};
  for (const TableRow& row : rows)
    for (size_t c = 0; c < ColumnCount; ++c) width[c] = std::max(width[c], row[c].size());
  std::string out;
  for (const TableRow& row : rows) {
    std::string line = " ";
    for (size_t c = 0; c < ColumnCount; ++c)
      line += " " + row[c] + std::string(width[c] - row[c].size() + 1, ' ');
    line.erase(line.find_last_not_of(' ') + 1);
    out += line + "\n";
  }
  return out;
}

std::string formatDefault(const nlohmann::json& value) { return value.is_null() ? "-" : value.dump(); }

std::string formatAlternatives(const MaterialModel& model) {
  std::string out;
  for (const auto& keys : model.alternatives) {
    std::string set;
    for (const std::string& key : keys) set += (set.empty() ? "" : " + ") + key;
    out += (out.empty() ? "" : " | ") + set;
  }
  return out;
}

std::string formatModel(const MaterialModel& model) {
  std::string out = model.type + ": " + model.description + "\n";
  out += "  citation: " + model.citation + "\n";
  std::vector<TableRow> rows{{"parameter", "kind", "default", "allowed", "description"}};
  for (const ParameterSpec& spec : model.parameters)
    rows.push_back(
        {spec.name, toString(spec.kind), formatDefault(spec.defaultValue), spec.allowed(), spec.description});
  out += formatColumns(rows);
  if (!model.alternatives.empty())
    out += "  give at most one of: " + formatAlternatives(model) + " (default: the first)\n";
  return out;
}

}  // namespace

std::string formatModelCatalog() {
  std::string out;
  for (const MaterialModel& model : materialModels()) out += (out.empty() ? "" : "\n") + formatModel(model);
  return out;
}

CLI::App* addModelsCommand(CLI::App& app, ModelsCommandOptions& options) {
  CLI::App* command =
      app.add_subcommand("models", "List every material model with its parameters, ranges and defaults");
  command->add_flag("--json", options.json, "Print the catalog as JSON");
  return command;
}

int runModelsCommand(const ModelsCommandOptions& options) {
  if (options.json)
    std::cout << materialCatalogJson().dump(2) << "\n";
  else
    std::cout << formatModelCatalog();
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
