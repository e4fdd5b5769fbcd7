#include "app/material_argument.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "materials/registry/material_file.h"

namespace scatterlab {

namespace {

// True for a readable regular file whose first non-blank byte is not '{' (a JSON material
// starts with it; a MERL table starts with its binary dimensions).
bool isTableFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream file(path, std::ios::binary);
  char c = 0;
  while (file.get(c))
    if (!std::isspace(static_cast<unsigned char>(c))) return c != '{';
  return false;  // empty or unreadable: the JSON reader says what is wrong with it
}

}  // namespace

nlohmann::json materialFromArgument(const std::string& argument) {
  if (!isInlineMaterial(argument) && isTableFile(argument)) return {{"type", "measured"}, {"file", argument}};
  return loadMaterialArgument(argument);
}

}  // namespace scatterlab
