// A MATERIAL argument of the command line as a material description: inline JSON (its first
// non-blank character is '{'), a JSON material file (the same, in the file), or else a
// measured table file, which becomes {"type": "measured", "file": PATH}: the measured model's
// reader then recognises the table by its content, not by the file's extension.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace scatterlab {

// Throws MaterialError naming the argument (not found, not readable, not valid JSON); the
// description is not validated (makeBsdf and completeMaterial do that).
nlohmann::json materialFromArgument(const std::string& argument);

}  // namespace scatterlab
