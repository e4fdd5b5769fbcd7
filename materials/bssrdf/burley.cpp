#include "materials/bssrdf/burley.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scatterlab {

double burleySampleRadius(double d, double u) {
  const double v = 1.0 - u;
  if (!(v > 0)) return INFINITY;
  const double g = 1.0 + 4.0 * v * (2.0 * v + std::sqrt(1.0 + 4.0 * v * v));
  const double cubeRoot = std::cbrt(g);
  const double x = 1.0 + cubeRoot + 1.0 / cubeRoot;
  // At u = 0, x = 4 exactly in real arithmetic; round-off must not make r negative.
  return std::max(3.0 * d * std::log(x / (4.0 * v)), 0.0);
}

BurleyProfile::BurleyProfile(const Rgb& albedo, const Rgb& shape) : albedo_(albedo), shape_(shape) {
  for (int c = 0; c < 3; ++c)
    if (!(albedo[c] >= 0 && albedo[c] <= 1) || !(shape[c] > 0) || !std::isfinite(shape[c]))
      throw std::invalid_argument("Burley profile: A must be in [0, 1] and d positive and finite");
}

Rgb BurleyProfile::eval(double r) const {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = burleyProfile(albedo_[c], shape_[c], r);
  return out;
}

double BurleyProfile::radiusCdf(int channel, double r) const {
  if (!(r > 0)) return 0.0;
  return std::clamp(burleyCumulative(1.0, shape_[channel], r), 0.0, 1.0);
}

double BurleyProfile::radiusPdf(int channel, double r) const {
  return r >= 0 ? burleyRadiusPdf(shape_[channel], r) : 0.0;
}

double BurleyProfile::sampleRadius(int channel, double u) const {
  return burleySampleRadius(shape_[channel], u);
}

}  // namespace scatterlab
