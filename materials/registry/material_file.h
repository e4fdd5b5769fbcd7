// Material arguments: inline JSON or the path of a material file (docs/design.md, "Material
// descriptions"). Parse errors name the source, the position and, inside a value, the key.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace scatterlab {

// True when a material argument is inline JSON (it starts with '{', or '[' which is refused
// with a message) rather than a file path.
bool isInlineMaterial(std::string_view argument);

// Parses a material argument: inline JSON when it starts with '{'; a measured file (a MERL
// table or an RGL file, told by content: measured/measured_file.h, whatever its name) is
// {"type": "measured", "file": argument}; any other file is parsed as JSON. Throws
// MaterialError naming the file (not found, not readable, over 4 MB: checked before it is
// read) or the source and position of a parse error, nesting beyond materials/core/json_text.h's
// limit, or a number that overflows a double (naming its key); inline JSON that is an array is
// refused (one material per argument). The result is not validated; makeBsdf/completeMaterial
// do that. From a file, relative values of path parameters (a measured material's "file"), at
// any depth, are made relative to the file's directory, so a material file and its data can
// move together.
nlohmann::json loadMaterialArgument(const std::string& argument);

// Calls `visit` with the value of every path parameter (a non-empty string) of `material` and of
// the materials nested in it, at any depth; `visit` may replace it (a measured material's "file"
// made relative to a directory, or pointed at a copy).
void forEachPathParameter(nlohmann::json& material, const std::function<void(nlohmann::json& path)>& visit);

}  // namespace scatterlab
