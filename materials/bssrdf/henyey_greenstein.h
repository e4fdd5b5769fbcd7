// The Henyey-Greenstein phase function (Henyey & Greenstein 1941, ApJ 93, eq. 3):
//   p(cos theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)),
// theta the angle between the propagation directions before and after scattering (g > 0:
// forward), normalised over the sphere. Sampled by inverting its CDF in cos theta; with the
// phi-uniform azimuth this is a forward / pdf / inverse triplet like the warps (warp.h).
#pragma once

#include <algorithm>

#include "materials/core/frame.h"

namespace scatterlab {

template <typename T> T henyeyGreenstein(const T& cosTheta, const T& g) {
  using std::sqrt;
  const T denominator = T(1) + g * g - T(2) * g * cosTheta;
  return (T(1) - g * g) / (T(4 * Pi) * denominator * sqrt(denominator));
}

// cos theta at CDF value u in [0, 1]. The textbook inverse (1 + g^2 - s^2) / (2g) with
// s = (1 - g^2) / (1 - g + 2 g u) cancels catastrophically as g -> 0; multiplied out, with
// x = 2u - 1, it is the division-free
//   cos = (x + g (x^2 + 3) / 2 + g^2 x + g^3 (x^2 - 1) / 2) / (1 + g x)^2,
// exact for every g in (-1, 1) (x at g = 0: uniform on the sphere).
inline double sampleHenyeyGreensteinCos(double g, double u) {
  const double x = 2.0 * u - 1.0;
  const double numerator = x + g * (0.5 * (x * x + 3.0) + g * (x + 0.5 * g * (x * x - 1.0)));
  return std::clamp(numerator / sqr(1.0 + g * x), -1.0, 1.0);
}

// The CDF in cos theta, (1 - g^2) / (2g) (1 / sqrt(1 + g^2 - 2 g cos) - 1 / (1 + g)), written
// without the division by g: the inverse of sampleHenyeyGreensteinCos.
inline double henyeyGreensteinCdf(double g, double cosTheta) {
  const double root = std::sqrt(1.0 + g * g - 2.0 * g * cosTheta);
  // (1/root - 1/(1+g)) / (2g) = (1 + g - root) / (2 g root (1 + g)), and
  // 1 + g - root = ((1 + g)^2 - root^2) / (1 + g + root) = 2 g (1 + cos) / (1 + g + root).
  return std::clamp((1.0 - g * g) * (1.0 + cosTheta) / (root * (1.0 + g) * (1.0 + g + root)), 0.0, 1.0);
}

// A direction scattered from the propagation direction w (unit): cos theta by the CDF
// inverse, phi = 2 pi u.y around w. Its density per solid angle is henyeyGreenstein(dot).
inline Vec3d sampleHenyeyGreenstein(const Vec3d& w, double g, const Vec2d& u) {
  const double cosTheta = sampleHenyeyGreensteinCos(g, u.x);
  const double sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
  const double phi = 2.0 * Pi * u.y;
  return Framed::fromNormal(w).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
}

}  // namespace scatterlab
