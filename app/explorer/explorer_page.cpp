#include "app/explorer/explorer_page.h"

#include <fstream>
#include <map>
#include <sstream>

#include "app/lab/embedded_assets.h"
#include "materials/core/atomic_file.h"
#include "materials/core/temporary_files.h"
#include "materials/registry/material_file.h"
#include "materials/registry/parameter_spec.h"
#include "validation/chi_square_images.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Embedded file -> where it goes in the explorer's directory.
constexpr std::pair<const char*, const char*> PageFiles[] = {
    {"explorer/index.html", "index.html"},
    {"explorer/scatterlab-api.js", "assets/scatterlab-api.js"},
    {"explorer/explorer-plots.js", "assets/explorer-plots.js"},
    {"explorer/explorer.js", "assets/explorer.js"},
    {"explorer/explorer.css", "assets/explorer.css"},
    {"explorer/scatterlab-wasm.js", "assets/scatterlab-wasm.js"},
};

std::string readBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream bytes;
  if (file) bytes << file.rdbuf();
  if (!file.is_open() || file.bad())
    throw MaterialError("material key \"file\": \"" + path +
                        "\" cannot be read for the explorer; allowed: a readable measured table file");
  return bytes.str();
}

struct EmbeddedTable {
  std::string path;    // in the page's file system, what the material's "file" becomes
  std::string script;  // relative to index.html
  std::string label;   // the original file name
};

// Writes each distinct table once, as tables/K-NAME.js, and points the materials at the copies.
class TableWriter {
 public:
  explicit TableWriter(fs::path dir) : dir_(std::move(dir)) {}

  json embed(json material, json& tables) {
    forEachPathParameter(material, [&](json& value) {
      const std::string original = value.get<std::string>();
      auto found = written_.find(original);
      if (found == written_.end()) found = written_.emplace(original, write(original)).first;
      const EmbeddedTable& table = found->second;
      value = table.path;
      bool listed = false;
      for (const json& known : tables) listed = listed || known["path"] == table.path;
      if (!listed) tables.push_back({{"path", table.path}, {"script", table.script}, {"label", table.label}});
    });
    return material;
  }
  size_t count() const { return written_.size(); }
  uintmax_t bytes() const { return bytes_; }

 private:
  EmbeddedTable write(const std::string& original) {
    const std::string name = fs::path(original).filename().string();
    const std::string stem = std::to_string(written_.size() + 1) + "-" + safeFileStem(name);
    EmbeddedTable table{"/tables/" + stem, "tables/" + stem + ".js", name};
    const std::string text = "(window.scatterlabTables = window.scatterlabTables || {})[" +
                             json(table.path).dump() + "] =\n\"" + base64(readBytes(original)) + "\";\n";
    createDirectoriesUninterrupted(dir_ / "tables");
    writeTextFileAtomically(dir_ / table.script, text);
    bytes_ += text.size();
    return table;
  }

  fs::path dir_;
  std::map<std::string, EmbeddedTable> written_;
  uintmax_t bytes_ = 0;
};

}  // namespace

json ExplorerWritten::toJson() const { return {{"tables", tables}, {"bytes", bytes}}; }

std::string base64(std::string_view bytes) {
  static constexpr char Alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const uint32_t v =
        uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int shift = 18; shift >= 0; shift -= 6) out += Alphabet[(v >> shift) & 63];
  }
  if (const size_t rest = bytes.size() - i; rest > 0) {
    const uint32_t v =
        uint32_t(uint8_t(bytes[i])) << 16 | (rest == 2 ? uint32_t(uint8_t(bytes[i + 1])) << 8 : 0);
    out += Alphabet[(v >> 18) & 63];
    out += Alphabet[(v >> 12) & 63];
    out += rest == 2 ? Alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

ExplorerWritten writeExplorer(const fs::path& dir, const std::vector<ExplorerMaterial>& materials) {
  createDirectoriesUninterrupted(dir / "assets");
  ExplorerWritten written;
  for (const auto& [asset, target] : PageFiles) {
    const std::string_view text = embeddedAsset(asset).text();
    writeTextFileAtomically(dir / target, text);
    written.bytes += text.size();
  }
  TableWriter tables(dir);
  json preload = json::array();
  for (const ExplorerMaterial& m : materials) {
    json tableList = json::array();
    json material = tables.embed(m.material, tableList);
    preload.push_back({{"id", m.id}, {"name", m.name}, {"material", material}, {"tables", tableList}});
  }
  const std::string preloadText =
      "// The materials this explorer was written with (scatterlab explore; docs/explorer.md).\n"
      "window.scatterlabPreload = " +
      json{{"materials", preload}}.dump(1) + ";\n";
  writeTextFileAtomically(dir / "assets" / "preload.js", preloadText);
  written.bytes += preloadText.size() + tables.bytes();
  written.tables = tables.count();
  writeTextFileAtomically(
      dir / ExplorerMarkerFile,
      json{{"generator", ExplorerGenerator}, {"materials", preload.size()}, {"written", written.toJson()}}
              .dump(2) +
          "\n");
  return written;
}

}  // namespace scatterlab
