// A directory of generated measured-style MERL tables with a manifest (bundle.json) that
// records what each file was made from (its fit line and perturbation), so a table whose
// source has not changed is kept and a second run costs nothing. `scatterlab synth --bundle`
// keeps the named bundle in one; `scatterlab lab` keeps its showcase tables in another.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace scatterlab {

class TableCache {
 public:
  // `directory` must exist. The manifest is read now; an unreadable one counts as empty.
  explicit TableCache(std::filesystem::path directory);

  const std::filesystem::path& directory() const { return directory_; }
  std::filesystem::path manifestPath() const;
  // NAME.binary in the directory.
  std::filesystem::path file(const std::string& name) const;
  // True when the manifest records `source` for `name` and the file has a MERL table's size.
  bool holds(const std::string& name, const nlohmann::json& source) const;
  // Records that file(name) was written from `source` and rewrites the manifest atomically.
  void record(const std::string& name, const std::string& category, const nlohmann::json& source);

 private:
  std::filesystem::path directory_;
  nlohmann::json manifest_;
};

}  // namespace scatterlab
