// OpenEXR input and output (OpenEXR 3.1): float RGB images with optional extra layers.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "integrator/image.h"

namespace scatterlab {

// One layer of an EXR file: three channels named `prefix.X` for X in `channelNames` (just X
// for the unnamed main layer), from a 3-channel image.
struct ExrLayer {
  std::string prefix;                       // "" for the main RGB layer
  std::array<std::string, 3> channelNames;  // {"R", "G", "B"} or {"X", "Y", "Z"}
  const Image* image = nullptr;
};

// Writes the layers (all of one size) as 32-bit float channels, ZIP-compressed, atomically:
// a failure leaves no file at `path` (materials/core/atomic_file.h). Throws RenderInputError
// naming the file when it cannot be written.
void writeExr(const std::filesystem::path& path, const std::vector<ExrLayer>& layers);

// The most pixels readExrRgb reads: 8192 x 4096, 0.4 GB as float RGB (an environment map
// then needs about as much again for its sampling tables).
inline constexpr long MaxExrPixels = 1L << 25;

// Reads the R, G and B channels (or Y, as grey, when the file has no colour) of an EXR file's
// data window into a 3-channel float image, any stored pixel type converted to float. Throws
// RenderInputError naming the file and the problem: not found, a directory, not an EXR file,
// truncated or otherwise unreadable, too many pixels, no R, G, B or Y channels. `what` begins
// the message ("environment map"). `maxPixels` lowers the pixel limit (a fuzz harness's, so that
// an input claiming a huge image costs little; fuzz/harness/exr_environment_map.cpp).
Image readExrRgb(const std::filesystem::path& path, const std::string& what = "EXR file",
                 long maxPixels = MaxExrPixels);

// The channel names of an EXR file, in the file's (alphabetical) order. Throws
// RenderInputError like readExrRgb.
std::vector<std::string> readExrChannelNames(const std::filesystem::path& path);

}  // namespace scatterlab
