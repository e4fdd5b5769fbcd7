#include "materials/registry/material_file.h"

#include <filesystem>
#include <string_view>
#include <vector>

#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/core/quoted.h"
#include "materials/measured/measured_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// Parses a material's text with the limits every JSON input has (materials/core/json_text.h),
// in the words of material errors.
json parseMaterialText(std::string_view text, const std::string& source) {
  try {
    return parseJsonText(text, source);
  } catch (const JsonTextError& error) {
    const JsonTextProblem& problem = error.problem();
    if (problem.kind == JsonTextProblem::Kind::NumberOverflow)
      throw MaterialError("material key " + inQuotes(problem.key) + ": " + shortened(problem.detail) +
                          " is too large for a double (" + source +
                          "); allowed: a finite number, |x| < 1.8e308");
    if (problem.kind != JsonTextProblem::Kind::Syntax) throw MaterialError(error.what());
    const std::string detail = source + ", " + shortenLongValues(problem.detail);
    if (problem.key.empty())
      throw MaterialError(detail + "; allowed: a JSON object such as {\"type\": \"lambertian\"}");
    throw MaterialError("material key " + inQuotes(problem.key) + ": not valid JSON (" + detail +
                        "); allowed: a JSON value, numbers finite (NaN and Infinity are not JSON)");
  }
}

std::string readMaterialFile(const std::string& path) {
  try {
    return readFileBounded(path, MaxJsonFileBytes, "material file");
  } catch (const InputFileError& error) {
    throw MaterialError(
        std::string(error.what()) +
        "; allowed: inline JSON starting with '{', or the path of a readable JSON file of at most " +
        describeBytes(MaxJsonFileBytes));
  }
}

}  // namespace

bool isInlineMaterial(std::string_view argument) {
  const auto first = argument.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && (argument[first] == '{' || argument[first] == '[');
}

nlohmann::json loadMaterialArgument(const std::string& argument) {
  if (isInlineMaterial(argument)) {
    json material = parseMaterialText(argument, "inline JSON");
    if (material.is_array())
      throw MaterialError("inline JSON: " + formatValue(material) +
                          " is an array; allowed: one material per argument, a JSON object such as "
                          "{\"type\": \"lambertian\"} (give several materials as several arguments)");
    return material;
  }
  // A measured file is told by its first bytes, whatever its name.
  if (measuredFormatOf(argument)) return json{{"type", "measured"}, {"file", argument}};
  const std::string text = readMaterialFile(argument);
  // Neither a measured file nor JSON: say what the MERL reader found as well (a table cut
  // short, a damaged header), not only that the text is not JSON.
  if (!isInlineMaterial(text))
    throw MaterialError("material file " + inQuotes(argument) +
                        ": neither JSON (it does not start with '{') nor a measured file (" +
                        notMeasuredReason(argument) +
                        "); allowed: a JSON material file, a MERL .binary table or an RGL .bsdf file");
  json material = parseMaterialText(text, "material file " + inQuotes(argument));
  const std::filesystem::path directory = std::filesystem::path(argument).parent_path();
  forEachPathParameter(material, [&](json& entry) {
    const std::filesystem::path path(entry.get<std::string>());
    if (path.is_relative()) entry = (directory / path).lexically_normal().string();
  });
  return material;
}

// Iterative: the depth is limited when the text is parsed, but the walk must not depend on that.
void forEachPathParameter(json& root, const std::function<void(json& path)>& visit) {
  std::vector<json*> stack{&root};
  while (!stack.empty()) {
    json& value = *stack.back();
    stack.pop_back();
    if (value.is_array()) {
      for (json& element : value) stack.push_back(&element);
      continue;
    }
    if (!value.is_object()) continue;
    const auto type = value.find("type");
    const MaterialModel* model =
        type != value.end() && type->is_string() ? findMaterialModel(type->get<std::string>()) : nullptr;
    for (auto& [key, entry] : value.items()) {
      const ParameterSpec* spec = model ? model->findParameter(key) : nullptr;
      if (spec && spec->kind == ParameterKind::Path && entry.is_string() && !entry.get<std::string>().empty())
        visit(entry);
      else
        stack.push_back(&entry);
    }
  }
}

}  // namespace scatterlab
