// A conductor's complex index (eta, k) from two quantities a fit can tell apart: the
// normal-incidence reflectance r and the "edge tint" g, which sets how the reflectance turns
// toward white at grazing angles (Gulbrandsen 2014, "Artist Friendly Metallic Fresnel", JCGT
// 3(4), eqs. 3-4; docs/references.md, "Conductor index from reflectance and edge tint"). For r
// in [0, 1) and g in [0, 1]:
//   eta = g (1 - r) / (1 + r) + (1 - g) (1 + sqrt r) / (1 - sqrt r),
//   k   = sqrt((r (eta + 1)^2 - (eta - 1)^2) / (1 - r)),
// which has normal-incidence reflectance ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2) = r for every g:
// g = 0 is the dielectric with that reflectance (k = 0), g = 1 the smallest eta (the most
// metallic edge). The map is one-to-one for k >= 0, and its inverse takes any real metal's
// index to (r, g). Templated for ceres::Jet (fitting/lobe_kernels.h).
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

template <typename T> struct ComplexIndexT { T eta, k; };

template <typename T> ComplexIndexT<T> indexFromReflectanceAndEdgeTint(const T& r, const T& g) {
  using std::sqrt;
  const T root = sqrt(r);
  const T nMin = (T(1) - r) / (T(1) + r);
  const T nMax = (T(1) + root) / (T(1) - root);
  const T eta = g * nMin + (T(1) - g) * nMax;
  const T k2 = (r * sqr(eta + T(1)) - sqr(eta - T(1))) / (T(1) - r);
  return {eta, safeSqrt(k2)};
}

// The inverse for a real index with k >= 0: r from (eta, k), then g where eta sits between
// the two ends above (clamped to [0, 1] for an index outside the family: k with eta > nMax).
inline Vec2d reflectanceAndEdgeTintOf(double eta, double k) {
  const double r = (sqr(eta - 1.0) + sqr(k)) / (sqr(eta + 1.0) + sqr(k));
  const double root = std::sqrt(r);
  const double nMin = (1.0 - r) / (1.0 + r), nMax = (1.0 + root) / (1.0 - root);
  return {r, std::clamp((nMax - eta) / (nMax - nMin), 0.0, 1.0)};
}

}  // namespace scatterlab
