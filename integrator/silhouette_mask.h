// Which pixels of a render show a sphere, classified from the camera alone as the peers'
// exr_stats.py does: a pixel is "sphere" when the ray through its centre passes the sphere's
// centre closer than radius - 3 pixel widths, "background" when farther than radius + 3 pixel
// widths (one pixel width = the pixel's size at the distance of the sphere's centre), neither
// in between. The 3-pixel margin keeps every pixel footprint wholly on one side of the
// silhouette, so sphere means compare across renderers and resolutions.
#pragma once

#include <cstdint>
#include <vector>

#include "integrator/camera.h"
#include "integrator/image.h"
#include "integrator/shapes.h"

namespace scatterlab {

enum class PixelRegion : uint8_t { Sphere, Background, Edge };

struct SilhouetteMask {
  int width = 0, height = 0;
  std::vector<PixelRegion> regions;  // row-major, row 0 at the top

  PixelRegion at(int x, int y) const { return regions[size_t(y) * width + x]; }
};

SilhouetteMask silhouetteMask(const PinholeCamera& camera, const Sphere& sphere, double marginPixels = 3.0);

// exr_stats.py's statistics of one region: mean and standard deviation per channel and of the
// channel average, min and max of the channel average.
struct RegionStatistics {
  size_t pixels = 0;
  Rgb meanRgb{0.0}, stdRgb{0.0};
  double mean = 0.0, std = 0.0, min = 0.0, max = 0.0;
};

RegionStatistics regionStatistics(const Image& image, const SilhouetteMask& mask, PixelRegion region);

}  // namespace scatterlab
