// Reading an equirectangular environment map from an OpenEXR file, with every check that
// Environment::fromMap needs turned into a message for the user.
//
// Negative values. Maps converted from wider gamuts carry small negative components where a
// colour lies outside Rec.709 (each of the four CC0 maps in data/envmaps has some, down to
// -0.3% of its mean). Radiance cannot be negative, but rejecting those maps would reject most
// real HDRIs, so a negative value no larger in magnitude than NegativeTolerance times the
// map's mean value (over all pixels and channels) is set to 0 and counted; anything more
// negative is an error, as are NaN and infinity.
#pragma once

#include <cstddef>
#include <filesystem>

#include "integrator/exr_io.h"
#include "integrator/image.h"

namespace scatterlab {

inline constexpr double NegativeTolerance = 0.01;

struct EnvironmentMapFile {
  Image image;                  // finite, >= 0, width == 2 x height
  size_t clampedNegatives = 0;  // values that were slightly negative and are now 0
  double mostNegative = 0.0;    // the most negative of them (0 when none)
};

// The map's RGB, checked: readable OpenEXR (exr_io.h), width exactly twice the height, every
// value finite and not below -NegativeTolerance x the mean. Throws RenderInputError naming the
// file and, for a bad value, the pixel (column, row from the top), channel and value.
// `maxPixels` as readExrRgb's.
EnvironmentMapFile readEnvironmentMap(const std::filesystem::path& path, long maxPixels = MaxExrPixels);

}  // namespace scatterlab
