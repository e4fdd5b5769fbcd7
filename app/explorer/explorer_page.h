// Writes the explorer (docs/explorer.md): a static page that runs scatterlab's model code
// compiled to WebAssembly, opened from the file system. `scatterlab explore` writes it as its
// own directory; the lab report writes one into DIR/explorer/, preloaded with its materials.
//
// DIR/index.html, DIR/assets/ (the page's script and style sheet, and scatterlab-wasm.js, the
// WebAssembly module as one JavaScript file: all embedded in the executable), DIR/assets/
// preload.js (the given materials), DIR/tables/K-NAME.js (each measured table a given material
// names, base64 in a script: a page opened from file:// may load scripts beside it, not read
// files), and DIR/explorer.json (what was written; marks the directory as an explorer).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

inline constexpr const char* ExplorerMarkerFile = "explorer.json";
inline constexpr const char* ExplorerGenerator = "scatterlab explore";

struct ExplorerMaterial {
  std::string id;    // selects it from the page's address: index.html#ID
  std::string name;  // shown in the page's list
  nlohmann::json material;
};

struct ExplorerWritten {
  size_t tables = 0;    // measured tables embedded
  uintmax_t bytes = 0;  // everything written
  nlohmann::json toJson() const;
};

// Writes the explorer into `dir` (created if missing). Every path parameter of the materials (a
// measured material's "file") is embedded as a table and pointed at the copy in the page's file
// system. Throws MaterialError naming a table file that cannot be read.
ExplorerWritten writeExplorer(const std::filesystem::path& dir,
                              const std::vector<ExplorerMaterial>& materials);

// RFC 4648 base64 of `bytes` (the tables' form in their scripts).
std::string base64(std::string_view bytes);

}  // namespace scatterlab
