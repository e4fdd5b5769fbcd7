#include "materials/registry/material_file.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

#include "materials/measured/measured_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// The key whose value the parser is reading, so that a parse error inside a value (NaN is
// not JSON) can still name the key. A key at depth d starts; the event that completes a
// value at depth d (a scalar, or the end of an array or object) ends it.
class KeyTracker {
 public:
  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    const auto level = static_cast<size_t>(depth);
    switch (event) {
      case json::parse_event_t::key:
        keys_.resize(level > 0 ? level - 1 : 0);
        keys_.push_back(parsed.get<std::string>());
        break;
      case json::parse_event_t::value:
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (level > 0 && keys_.size() == level) keys_.pop_back();
        break;
      default: break;
    }
    return true;
  }
  // "alpha", or "outer.inner" inside nested objects; empty outside any value.
  std::string currentKey() const {
    std::string out;
    for (const std::string& key : keys_) out += (out.empty() ? "" : ".") + key;
    return out;
  }

 private:
  std::vector<std::string> keys_;
};

// "line 1, column 22: syntax error while parsing value - ..." from nlohmann's what().
std::string parseErrorDetail(const json::parse_error& error) {
  std::string text = error.what();
  if (const auto id = text.find("] "); text.starts_with("[json.exception.") && id != std::string::npos)
    text.erase(0, id + 2);
  constexpr std::string_view Prefix = "parse error at ";
  if (text.starts_with(Prefix)) text.erase(0, Prefix.size());
  return text;
}

json parseJsonText(const std::string& text, const std::string& source) {
  KeyTracker tracker;
  try {
    return json::parse(text, std::ref(tracker));
  } catch (const json::parse_error& error) {
    const std::string detail = source + ", " + parseErrorDetail(error);
    const std::string key = tracker.currentKey();
    if (key.empty())
      throw MaterialError(detail + "; allowed: a JSON object such as {\"type\": \"lambertian\"}");
    throw MaterialError("material key " + inQuotes(key) + ": not valid JSON (" + detail +
                        "); allowed: a JSON value, numbers finite (NaN and Infinity are not JSON)");
  }
}

std::string readMaterialFile(const std::string& path) {
  const std::string source = "material file " + inQuotes(path);
  const std::string allowed =
      "; allowed: inline JSON starting with '{', or the path of a readable JSON file, MERL .binary table or "
      "RGL .bsdf file";
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw MaterialError(source + ": not found" + allowed);
  if (std::filesystem::is_directory(status)) throw MaterialError(source + ": is a directory" + allowed);
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  if (file) contents << file.rdbuf();
  if (!file.is_open() || file.bad()) throw MaterialError(source + ": not readable" + allowed);
  return contents.str();
}

// Path parameters of every material object in `value` (nested ones too) made relative to
// `directory` when they are relative paths.
void resolveRelativePaths(json& value, const std::filesystem::path& directory) {
  if (value.is_array()) {
    for (json& element : value) resolveRelativePaths(element, directory);
    return;
  }
  if (!value.is_object()) return;
  const auto type = value.find("type");
  const MaterialModel* model =
      type != value.end() && type->is_string() ? findMaterialModel(type->get<std::string>()) : nullptr;
  for (auto& [key, entry] : value.items()) {
    const ParameterSpec* spec = model ? model->findParameter(key) : nullptr;
    if (spec && spec->kind == ParameterKind::Path && entry.is_string() && !entry.get<std::string>().empty()) {
      const std::filesystem::path path(entry.get<std::string>());
      if (path.is_relative()) entry = (directory / path).lexically_normal().string();
    } else {
      resolveRelativePaths(entry, directory);
    }
  }
}

}  // namespace

bool isInlineMaterial(std::string_view argument) {
  const auto first = argument.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && argument[first] == '{';
}

nlohmann::json loadMaterialArgument(const std::string& argument) {
  if (isInlineMaterial(argument)) return parseJsonText(argument, "inline JSON");
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
  json material = parseJsonText(text, "material file " + inQuotes(argument));
  resolveRelativePaths(material, std::filesystem::path(argument).parent_path());
  return material;
}

}  // namespace scatterlab
