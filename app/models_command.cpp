#include "app/models_command.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <iostream>
#include <vector>

#include "app/exit_code.h"
#include "app/plugin_option.h"
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
  if (!model.plugin.empty()) out += "  plugin: " + model.plugin + "\n";
  std::vector<TableRow> rows{{"parameter", "kind", "default", "allowed", "description"}};
  for (const ParameterSpec& spec : model.parameters)
    rows.push_back(
        {spec.name, toString(spec.kind), formatDefault(spec.defaultValue), spec.allowed(), spec.description});
  out += formatColumns(rows);
  if (!model.alternatives.empty())
    out += "  give at most one of: " + formatAlternatives(model) + " (default: the first)\n";
  return out;
}

// ---- Markdown (docs/models.md) ----

// Text for a Markdown table cell or paragraph, escaped where Markdown would read it as markup:
// '|' ends a cell, '*' and a word-boundary '_' open emphasis (an '_' inside a word, theta_h, is
// plain text in GitHub's Markdown), '<' before a letter, '/', '!' or '?' opens a tag. Backquotes
// are left alone: the descriptions use them in pairs, for commands.
std::string markdownText(const std::string& text) {
  const auto isWordChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i], next = i + 1 < text.size() ? text[i + 1] : ' ';
    const bool insideWord = i > 0 && isWordChar(text[i - 1]) && isWordChar(next);
    const bool opensTag =
        std::isalpha(static_cast<unsigned char>(next)) || next == '/' || next == '!' || next == '?';
    if (c == '|' || c == '*' || (c == '_' && !insideWord) || (c == '<' && opensTag)) out += '\\';
    out += c;
  }
  return out;
}

std::string markdownCode(const std::string& text) { return "`" + text + "`"; }

std::string kindName(MaterialKind kind) {
  return kind == MaterialKind::Bsdf ? "BSDF" : "subsurface (BSSRDF)";
}

std::string markdownDefault(const ParameterSpec& spec) {
  return spec.defaultValue.is_null() ? "none" : markdownCode(spec.defaultValue.dump());
}

std::string markdownAlternatives(const MaterialModel& model) {
  std::string out;
  for (const auto& keys : model.alternatives) {
    std::string set;
    for (const std::string& key : keys) set += (set.empty() ? "" : " + ") + markdownCode(key);
    out += (out.empty() ? "" : ", or ") + set;
  }
  return out;
}

std::string formatModelMarkdown(const MaterialModel& model) {
  std::string out = "## " + markdownCode(model.type) + "\n\n";
  out += markdownText(model.description) + ".\n\n";
  out += "- Kind: " + kindName(model.kind) + "\n";
  out += "- Citation: " + markdownText(model.citation) + "\n";
  if (!model.alternatives.empty())
    out += "- Alternatives: give at most one of " + markdownAlternatives(model) +
           " (all of its keys); with none given, the first applies\n";
  out += "\n| parameter | kind | allowed | default | description |\n|---|---|---|---|---|\n";
  for (const ParameterSpec& spec : model.parameters)
    out += "| " + markdownCode(spec.name) + " | " + toString(spec.kind) + " | " +
           markdownText(spec.allowed()) + " | " + markdownDefault(spec) + " | " +
           markdownText(spec.description) + (spec.required ? " (required)" : "") + " |\n";
  return out;
}

}  // namespace

std::string formatModelCatalogMarkdown() {
  std::string out =
      "# Material models\n\n"
      "<!-- Generated from the registry's catalogue by `scatterlab models --markdown`; do not edit. -->\n\n"
      "Every material model scatterlab builds, as the registry describes it: the catalogue that\n"
      "`scatterlab models` prints and `scatterlab models --json` writes. A material is a JSON object\n"
      "whose `type` is one of these; a key left out takes its default, and a value outside what is\n"
      "allowed is an error that names the key (docs/design.md, \"Material descriptions\").\n\n"
      "This page is generated: after changing a model's spec, run\n"
      "`scatterlab models --markdown > docs/models.md` (the `docs.models` test fails until the page\n"
      "and the registry agree).\n\n"
      "| type | kind | model |\n|---|---|---|\n";
  for (const MaterialModel& model : materialModels())
    out += "| " + markdownCode(model.type) + " | " + kindName(model.kind) + " | " +
           markdownText(model.description) + " |\n";
  for (const MaterialModel& model : materialModels()) {
    out += '\n';
    out += formatModelMarkdown(model);
  }
  return out;
}

std::string formatModelCatalog() {
  std::string out;
  for (const MaterialModel& model : materialModels()) {
    if (!out.empty()) out += '\n';
    out += formatModel(model);
  }
  return out;
}

CLI::App* addModelsCommand(CLI::App& app, ModelsCommandOptions& options) {
  CLI::App* command =
      app.add_subcommand("models", "List every material model with its parameters, ranges and defaults");
  CLI::Option* json = command->add_flag("--json", options.json, "Print the catalog as JSON");
  command
      ->add_flag("--markdown", options.markdown,
                 "Print the catalog as Markdown (the page committed as docs/models.md)")
      ->excludes(json);
  addPluginOption(*command);
  return command;
}

int runModelsCommand(const ModelsCommandOptions& options) {
  if (options.json)
    std::cout << materialCatalogJson().dump(2) << "\n";
  else if (options.markdown)
    std::cout << formatModelCatalogMarkdown();
  else
    std::cout << formatModelCatalog();
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
