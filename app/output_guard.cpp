#include "app/output_guard.h"

#include <sys/stat.h>

#include <optional>
#include <utility>

#include "app/exit_code.h"
#include "materials/core/quoted.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace fs = std::filesystem;

namespace {

struct Identity {
  fs::path canonical;
  std::optional<std::pair<dev_t, ino_t>> inode;  // when the path exists
};

Identity identify(const fs::path& path) {
  Identity id;
  std::error_code error;
  id.canonical = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) id.canonical = fs::absolute(path).lexically_normal();
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) id.inode = std::pair(status.st_dev, status.st_ino);
  return id;
}

bool isInside(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

bool endsWithAny(const std::string& name, const std::vector<std::string>& suffixes) {
  for (const std::string& suffix : suffixes)
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return true;
  return false;
}

}  // namespace

void refuseOutputOverInputs(const std::string& option, const fs::path& output, OutputKind kind,
                            const std::vector<InputPath>& inputs, const std::vector<std::string>& suffixes) {
  const Identity out = identify(output);
  for (const InputPath& input : inputs) {
    const Identity in = identify(input.path);
    const bool same = in.canonical == out.canonical || (in.inode && out.inode && *in.inode == *out.inode);
    std::string problem;
    if (same)
      problem = "is the " + input.what + " " + inQuotes(input.path.string()) + ", which it would overwrite";
    else if (kind == OutputKind::ReplacedDirectory && isInside(in.canonical, out.canonical))
      problem = "holds the " + input.what + " " + inQuotes(input.path.string()) +
                ", which replacing the directory would delete";
    else if (kind == OutputKind::FilesInDirectory && in.canonical.parent_path() == out.canonical &&
             endsWithAny(in.canonical.filename().string(), suffixes))
      problem = "holds the " + input.what + " " + inQuotes(input.path.string()) +
                ", a name this command writes there";
    if (!problem.empty())
      throw InputError(option + ": " + inQuotes(output.string()) + " " + problem +
                       "; allowed: an output path that is not an input");
  }
}

std::vector<fs::path> materialInputFiles(const nlohmann::json& material) {
  std::vector<fs::path> files;
  // Iterative: the description may be deep (its depth is limited when it is parsed, but not
  // every description was parsed from text).
  std::vector<const nlohmann::json*> stack{&material};
  while (!stack.empty()) {
    const nlohmann::json& value = *stack.back();
    stack.pop_back();
    if (value.is_array()) {
      for (const nlohmann::json& element : value) stack.push_back(&element);
      continue;
    }
    if (!value.is_object()) continue;
    const auto type = value.find("type");
    const MaterialModel* model =
        type != value.end() && type->is_string() ? findMaterialModel(type->get<std::string>()) : nullptr;
    for (const auto& [key, entry] : value.items()) {
      const ParameterSpec* spec = model ? model->findParameter(key) : nullptr;
      if (spec && spec->kind == ParameterKind::Path && entry.is_string())
        files.emplace_back(entry.get<std::string>());
      else
        stack.push_back(&entry);
    }
  }
  return files;
}

void addMaterialInputs(std::vector<InputPath>& inputs, const std::string& argument,
                       const nlohmann::json& material) {
  if (!isInlineMaterial(argument)) inputs.push_back({"material file", argument});
  for (const fs::path& file : materialInputFiles(material)) inputs.push_back({"material's table", file});
}

}  // namespace scatterlab
