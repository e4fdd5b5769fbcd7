#include "app/table_cache.h"

#include <fstream>

#include "materials/core/atomic_file.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr const char* ManifestName = "bundle.json";
constexpr int ManifestFormat = 1;

json readManifest(const fs::path& path) {
  std::ifstream in(path);
  json manifest = in ? json::parse(in, nullptr, /*allow_exceptions=*/false) : json();
  if (!manifest.is_object() || manifest.value("format", 0) != ManifestFormat) manifest = json::object();
  manifest["format"] = ManifestFormat;
  if (!manifest.contains("materials") || !manifest["materials"].is_object())
    manifest["materials"] = json::object();
  return manifest;
}

}  // namespace

TableCache::TableCache(fs::path directory)
    : directory_(std::move(directory)), manifest_(readManifest(directory_ / ManifestName)) {}

fs::path TableCache::manifestPath() const { return directory_ / ManifestName; }

fs::path TableCache::file(const std::string& name) const { return directory_ / (name + ".binary"); }

bool TableCache::holds(const std::string& name, const json& source) const {
  const json& recorded = manifest_["materials"].value(name, json::object());
  std::error_code error;
  return recorded.value("source", json()) == source && fs::file_size(file(name), error) == merl::FileBytes &&
         !error;
}

void TableCache::record(const std::string& name, const std::string& category, const json& source) {
  manifest_["materials"][name] = {
      {"file", file(name).filename().string()}, {"category", category}, {"source", source}};
  writeTextFileAtomically(manifestPath(), manifest_.dump(2) + "\n");
}

}  // namespace scatterlab
