// Files compiled into the executable (app/lab/report_assets.cmake). Those named report/NAME
// (Chart.js and its licence, the report's own script and style sheet) are copied into every
// report as assets/NAME.
#pragma once

#include <span>
#include <string_view>

namespace scatterlab {

struct EmbeddedAsset {
  std::string_view name;  // "report/chart.umd.min.js"
  std::span<const unsigned char> bytes;

  std::string_view text() const { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }
};

// Every embedded file (defined in the generated lab_embedded_assets.cpp).
std::span<const EmbeddedAsset> embeddedAssets();

// The file called `name`; std::logic_error when there is none (a build that lacks it is a bug).
const EmbeddedAsset& embeddedAsset(std::string_view name);

// The version of the embedded Chart.js (from its package.json at build time).
std::string_view chartJsVersion();

}  // namespace scatterlab
