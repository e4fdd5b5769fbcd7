// 8-bit sRGB previews of linear renders (libpng).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "integrator/image.h"

namespace scatterlab {

// The sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
double srgbEncode(double linear);

// 8-bit sRGB of the first three channels of `image` times 2^exposure, clamped to [0, 1] and
// rounded; rows top to bottom. A non-finite value (which the renderer never produces) maps to
// 0 rather than to an undefined byte.
std::vector<uint8_t> toSrgb8(const Image& image, double exposure = 0.0);

// Writes 8-bit RGB rows (top to bottom) as a PNG, atomically (a failure leaves no file at
// `path`). Throws RenderInputError naming the file when it cannot be written.
void writePngRgb8(const std::filesystem::path& path, int width, int height, const std::vector<uint8_t>& rgb);

// toSrgb8 + writePngRgb8.
void writePngSrgb(const std::filesystem::path& path, const Image& image, double exposure = 0.0);

}  // namespace scatterlab
