#include "integrator/silhouette_mask.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scatterlab {

SilhouetteMask silhouetteMask(const PinholeCamera& camera, const Sphere& sphere, double marginPixels) {
  SilhouetteMask mask{camera.width(), camera.height(), {}};
  mask.regions.resize(size_t(mask.width) * mask.height);
  const double pixel = camera.pixelAngle() * glm::length(sphere.center - camera.eye());
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      const Ray ray = camera.generateRay(Vec2d(x + 0.5, y + 0.5));
      const Vec3d toCenter = sphere.center - ray.origin;
      const double along = glm::dot(toCenter, ray.direction);
      const double perpendicular = std::sqrt(std::max(0.0, glm::dot(toCenter, toCenter) - along * along));
      PixelRegion region = PixelRegion::Edge;
      if (perpendicular < sphere.radius - marginPixels * pixel) region = PixelRegion::Sphere;
      if (perpendicular > sphere.radius + marginPixels * pixel) region = PixelRegion::Background;
      mask.regions[size_t(y) * mask.width + x] = region;
    }
  return mask;
}

RegionStatistics regionStatistics(const Image& image, const SilhouetteMask& mask, PixelRegion region) {
  if (image.width() != mask.width || image.height() != mask.height)
    throw std::invalid_argument("regionStatistics: image and mask differ in size");
  RegionStatistics s;
  Rgb sum(0.0), sum2(0.0);
  double sumMean = 0.0, sumMean2 = 0.0;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      if (mask.at(x, y) != region) continue;
      const Rgb v = image.rgb(x, y);
      const double m = (v.x + v.y + v.z) / 3.0;
      ++s.pixels;
      sum += v;
      sum2 += v * v;
      sumMean += m;
      sumMean2 += m * m;
      s.min = std::min(s.min, m);
      s.max = std::max(s.max, m);
    }
  if (s.pixels == 0) return RegionStatistics{};
  const double n = double(s.pixels);
  s.meanRgb = sum / n;
  s.stdRgb = glm::sqrt(glm::max(sum2 / n - s.meanRgb * s.meanRgb, Rgb(0.0)));
  s.mean = sumMean / n;
  s.std = std::sqrt(std::max(0.0, sumMean2 / n - s.mean * s.mean));
  return s;
}

}  // namespace scatterlab
