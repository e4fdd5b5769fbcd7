// The sphere mask is exr_stats.py's: the same pixels, computed here once more by that
// script's own formula (line distance from the origin of the ray (X, 1, Y) from (0, -d, 0)).
#include <gtest/gtest.h>

#include "integrator/scene_presets.h"
#include "integrator/silhouette_mask.h"

namespace scatterlab {
namespace silhouette_mask_test {

TEST(SilhouetteMask, IsExrStatsMask) {
  for (const int size : {64, 256}) {
    const PinholeCamera camera =
        PinholeCamera::lookAt(Vec3d(0, -4, 0), Vec3d(0.0), Vec3d(0, 0, 1), 45.0, size, size);
    const SilhouetteMask mask = silhouetteMask(camera, presetSphere());
    const double t = std::tan(radians(45.0) / 2.0), d = 4.0, pix = 2.0 * t / size * d;
    int sphere = 0, background = 0;
    for (int row = 0; row < size; ++row)
      for (int i = 0; i < size; ++i) {
        const double x = (2.0 * (i + 0.5) / size - 1.0) * t, y = (2.0 * (row + 0.5) / size - 1.0) * t;
        const double perp = std::sqrt(d * d - d * d / (x * x + 1.0 + y * y));
        const PixelRegion expected = perp < 1.0 - 3 * pix   ? PixelRegion::Sphere
                                     : perp > 1.0 + 3 * pix ? PixelRegion::Background
                                                            : PixelRegion::Edge;
        EXPECT_EQ(mask.at(i, row), expected) << size << ": pixel " << i << ", " << row;
        sphere += expected == PixelRegion::Sphere;
        background += expected == PixelRegion::Background;
      }
    EXPECT_GT(sphere, size * size / 5);
    EXPECT_GT(background, size * size / 2);
  }
}

TEST(SilhouetteMask, StatisticsOfARegion) {
  const PinholeCamera camera =
      PinholeCamera::lookAt(Vec3d(0, -4, 0), Vec3d(0.0), Vec3d(0, 0, 1), 45.0, 32, 32);
  const SilhouetteMask mask = silhouetteMask(camera, presetSphere());
  Image image(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      image.setRgb(x, y, mask.at(x, y) == PixelRegion::Sphere ? Rgb(x % 2 ? 1.0 : 3.0, 2.0, 2.0) : Rgb(7.0));
  const RegionStatistics s = regionStatistics(image, mask, PixelRegion::Sphere);
  EXPECT_GT(s.pixels, 100u);
  EXPECT_NEAR(s.meanRgb.y, 2.0, 1e-12);
  EXPECT_NEAR(s.mean, (s.meanRgb.x + 4.0) / 3.0, 1e-12);
  EXPECT_NEAR(s.min, 5.0 / 3.0, 1e-6);
  EXPECT_NEAR(s.max, 7.0 / 3.0, 1e-6);
  EXPECT_NEAR(regionStatistics(image, mask, PixelRegion::Background).mean, 7.0, 1e-12);
}

}  // namespace silhouette_mask_test
}  // namespace scatterlab
