#include "app/table_cache.h"

#include "materials/core/atomic_file.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr const char* BundleManifestName = "bundle.json";
constexpr int ManifestFormat = 1;

// A missing, unreadable, oversized or malformed manifest is an empty cache (its tables are
// made again), never an error.
json readManifest(const fs::path& path) {
  json manifest;
  try {
    manifest = parseJsonText(readFileBounded(path, MaxJsonFileBytes, "table manifest"), path.string());
  } catch (const std::exception&) {
    manifest = json();
  }
  if (!manifest.is_object() || manifest.value("format", 0) != ManifestFormat) manifest = json::object();
  manifest["format"] = ManifestFormat;
  if (!manifest.contains("materials") || !manifest["materials"].is_object())
    manifest["materials"] = json::object();
  return manifest;
}

}  // namespace

TableCache::TableCache(fs::path directory)
    : directory_(std::move(directory)), manifest_(readManifest(directory_ / BundleManifestName)) {}

fs::path TableCache::manifestPath() const { return directory_ / BundleManifestName; }

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
