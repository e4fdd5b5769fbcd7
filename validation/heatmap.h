// False-colour PNG images of chi-square tables, so a person can see where a sampler is
// wrong: observed and expected counts share one colour scale; residuals
// (O - E) / sqrt(E) use a diverging scale clamped at +-5 sigma.
#pragma once

#include <filesystem>

#include "validation/spherical_grid.h"

namespace scatterlab {

enum class HeatmapScale {
  Sequential,  // 0 .. maximum: dark blue -> yellow (viridis-like)
  Diverging,   // -limit .. +limit: blue -> white -> red
};

// Writes `table` as an 8-bit RGB PNG, each cell `cellPixels` wide and tall, cos(theta) = 1
// at the top. `limit` is the value mapped to the end of the scale.
void writeHeatmapPng(const std::filesystem::path& path, const Table2D& table, HeatmapScale scale,
                     double limit, int cellPixels = 4);

}  // namespace scatterlab
