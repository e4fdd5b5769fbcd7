#include "validation/chi_square_images.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <nlohmann/json.hpp>

#include "materials/core/atomic_file.h"
#include "materials/core/temporary_files.h"
#include "validation/heatmap.h"

namespace scatterlab {

std::string safeFileStem(const std::string& label) {
  std::string s;
  for (char c : label) s += (std::isalnum((unsigned char)c) || c == '-' || c == '_' || c == '.') ? c : '_';
  if (s.size() > 80) s.resize(80);
  return s;
}

std::vector<std::string> chiSquareImageSuffixes() {
  return {"_observed.png", "_expected.png", "_residual.png", "_consistency.png", "_tables.json"};
}

void writeChiSquareImages(const std::filesystem::path& dir, const std::string& stem,
                          const ChiSquareResult& chi, const std::string& layout,
                          const Table2D* consistencyMaxError, double consistencyTolerance) {
  createDirectoriesUninterrupted(dir);
  double peak = 0;
  for (size_t i = 0; i < chi.observed.values.size(); ++i)
    peak = std::max({peak, chi.observed.values[i], chi.expected.values[i]});
  writeHeatmapPng(dir / (stem + "_observed.png"), chi.observed, HeatmapScale::Sequential, peak);
  writeHeatmapPng(dir / (stem + "_expected.png"), chi.expected, HeatmapScale::Sequential, peak);
  Table2D residual(chi.observed.rows, chi.observed.cols);
  for (size_t i = 0; i < residual.values.size(); ++i) {
    const double e = chi.expected.values[i], o = chi.observed.values[i];
    residual.values[i] = e > 0 ? (o - e) / std::sqrt(e) : (o > 0 ? INFINITY : 0.0);
  }
  writeHeatmapPng(dir / (stem + "_residual.png"), residual, HeatmapScale::Diverging, 5.0);
  nlohmann::json tables = {{"rows", chi.observed.rows},
                           {"cols", chi.observed.cols},
                           {"layout", layout},
                           {"observed", chi.observed.values},
                           {"expected", chi.expected.values}};
  if (consistencyMaxError) {
    writeHeatmapPng(dir / (stem + "_consistency.png"), *consistencyMaxError, HeatmapScale::Sequential,
                    10.0 * consistencyTolerance);
    tables["consistency_max_error"] = consistencyMaxError->values;
  }
  writeTextFileAtomically(dir / (stem + "_tables.json"), tables.dump());
}

}  // namespace scatterlab
