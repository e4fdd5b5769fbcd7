// Pixel reconstruction filters, applied by sampling (filter importance sampling: Ernst et al.
// 2006, "Filter Importance Sampling"; pbrt-v4's FilterSampler): each camera sample's film
// position is offset from the pixel centre with the filter's normalised density, so every
// sample has weight 1 and a pixel is the plain mean of its own samples. That keeps pixels
// independent of each other: any thread count gives the same image, and the per-pixel
// variance is that of a sample mean.
//   box:       uniform over the pixel (width 1), as Cycles' "Box" filter of width 1;
//   gaussian:  exp(-r^2 / (2 sigma^2)) truncated to the square |x|, |y| <= radius, sampled
//              exactly by Box-Muller (Box & Muller 1958) with rejection outside the square.
// Estimators that splat a film point onto the pixels around it (light tracing, BDPT) weigh it
// by the same normalised density (density), so both ways give a pixel the same value.
#pragma once

#include <cmath>
#include <stdexcept>

#include "integrator/sampler.h"

namespace scatterlab {

enum class FilterType { Box, Gaussian };

class PixelFilter {
 public:
  static PixelFilter box() { return PixelFilter(FilterType::Box, 0.0, 0.5); }
  // sigma > 0 and radius >= sigma (at least 68% of the untruncated mass kept per axis), in
  // pixels; std::invalid_argument otherwise.
  static PixelFilter gaussian(double sigma = 0.5, double radius = 1.5) {
    if (!(sigma > 0) || !(radius >= sigma) || !std::isfinite(radius))
      throw std::invalid_argument("PixelFilter: needs sigma > 0 and radius >= sigma");
    return PixelFilter(FilterType::Gaussian, sigma, radius);
  }

  FilterType type() const { return type_; }
  // Half the side of the filter's square support, in pixels (0.5 for the box).
  double sigma() const { return sigma_; }
  double radius() const { return radius_; }

  // The normalised density of sampleOffset at `offset` (pixels): it integrates to 1 over the
  // support. The truncated Gaussian keeps erf(radius / (sigma sqrt 2)) of its mass per axis.
  double density(const Vec2d& offset) const {
    if (std::abs(offset.x) > radius_ || std::abs(offset.y) > radius_) return 0.0;
    if (type_ == FilterType::Box) return 1.0;
    const double kept = std::erf(radius_ / (sigma_ * std::sqrt(2.0)));
    return std::exp(-(offset.x * offset.x + offset.y * offset.y) / (2.0 * sigma_ * sigma_)) /
           (2.0 * Pi * sigma_ * sigma_ * kept * kept);
  }

  // An offset from the pixel centre, in pixels, distributed as the normalised filter.
  Vec2d sampleOffset(SampleStream& random) const {
    if (type_ == FilterType::Box) return random.next2D() - Vec2d(0.5);
    for (;;) {  // accepted with probability erf(radius / (sigma sqrt 2))^2 >= 0.46
      const Vec2d u = random.next2D();
      const double r = sigma_ * std::sqrt(-2.0 * std::log1p(-u.x));
      const double phi = 2.0 * Pi * u.y;
      const Vec2d offset(r * std::cos(phi), r * std::sin(phi));
      if (std::abs(offset.x) <= radius_ && std::abs(offset.y) <= radius_) return offset;
    }
  }

 private:
  PixelFilter(FilterType type, double sigma, double radius) : type_(type), sigma_(sigma), radius_(radius) {}

  FilterType type_;
  double sigma_, radius_;
};

}  // namespace scatterlab
