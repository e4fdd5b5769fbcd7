#include "app/plugin_option.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/plugin_loader.h"

namespace scatterlab {

namespace {

namespace fs = std::filesystem;

constexpr const char* PluginPathVariable = "SCATTERLAB_PLUGIN_PATH";

// The *.so files of a directory, in name order (so the registry's order does not depend on the
// file system's).
std::vector<fs::path> librariesIn(const fs::path& directory) {
  std::vector<fs::path> libraries;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error))
    if (entry.path().extension() == ".so" && entry.is_regular_file(error)) libraries.push_back(entry.path());
  std::sort(libraries.begin(), libraries.end());
  return libraries;
}

}  // namespace

void addPluginOption(CLI::App& command) {
  command
      .add_option_function<std::vector<std::string>>(
          "--plugin",
          [](const std::vector<std::string>& libraries) {
            for (const std::string& library : libraries) loadPlugin(library, "--plugin");
          },
          "Load models from a plugin library (repeatable; also SCATTERLAB_PLUGIN_PATH)")
      ->type_name("LIB")
      ->allow_extra_args(false);
}

void loadPluginsFromEnvironment() {
  const char* value = std::getenv(PluginPathVariable);
  if (!value) return;
  const std::string list = value;
  size_t begin = 0;
  while (begin <= list.size()) {
    const size_t end = std::min(list.find(':', begin), list.size());
    const fs::path entry = list.substr(begin, end - begin);
    begin = end + 1;
    if (entry.empty()) continue;
    std::error_code error;
    if (fs::is_directory(entry, error)) {
      for (const fs::path& library : librariesIn(entry)) loadPlugin(library, PluginPathVariable);
    } else {
      loadPlugin(entry, PluginPathVariable);
    }
  }
}

}  // namespace scatterlab
