// Material arguments: inline JSON or the path of a material file (docs/design.md, "Material
// descriptions"). Parse errors name the source, the position and, inside a value, the key.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace scatterlab {

// True when a material argument is inline JSON rather than a file path.
bool isInlineMaterial(std::string_view argument);

// Parses a material argument: inline JSON when it starts with '{', a file path otherwise. A
// measured file (a MERL table or an RGL file, told by content: measured/measured_file.h) is
// {"type": "measured", "file": argument}; any other file is parsed as JSON.
// Throws MaterialError naming the file (not found, not readable) or the source and position
// of a parse error. The result is not validated; makeBsdf/completeMaterial do that. From a
// file, relative values of path parameters (a measured material's "file"), at any depth, are
// made relative to the file's directory, so a material file and its data can move together.
nlohmann::json loadMaterialArgument(const std::string& argument);

}  // namespace scatterlab
