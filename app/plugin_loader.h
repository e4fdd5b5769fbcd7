// Loading plugins (materials/registry/plugin.h): shared libraries that add models to the registry
// before a command reads it.
#pragma once

#include <filesystem>
#include <string>

namespace scatterlab {

// Loads the plugin `library` and registers its models. `source` says where the name came from
// ("--plugin", "SCATTERLAB_PLUGIN_PATH") for the messages. A library already loaded (the same
// file, by its canonical path) is not loaded again. Throws InputError for a missing file, a
// library that cannot be loaded, one that is not a scatterlab plugin or was built against
// another scatterlab (ABI stamp), and MaterialError for a model the registry refuses (a type
// that exists, a parameter without a default); every message names the library.
void loadPlugin(const std::filesystem::path& library, const std::string& source);

}  // namespace scatterlab
