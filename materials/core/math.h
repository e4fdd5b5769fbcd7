// Scalar helpers shared by every model kernel.
//
// Kernels are templated on the scalar type T (double for rendering, ceres::Jet for fitting).
// Functions here call sqrt/acos/... unqualified after `using std::...` so that the Jet
// overloads are found by argument-dependent lookup, and they guard singular points so that
// the value AND the derivative stay finite (docs/design.md, "One model code").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace scatterlab {

template <typename T> using Vec2 = glm::vec<2, T, glm::defaultp>;
template <typename T> using Vec3 = glm::vec<3, T, glm::defaultp>;
using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;
// Linear RGB, Rec.709 primaries (docs/design.md, "Units and colour").
template <typename T> using RgbT = Vec3<T>;
using Rgb = RgbT<double>;

inline constexpr double Pi = 3.14159265358979323846;
inline constexpr double InvPi = 1.0 / Pi;
inline constexpr double Inv2Pi = 1.0 / (2.0 * Pi);
inline constexpr double Inv4Pi = 1.0 / (4.0 * Pi);
inline constexpr double PiOver2 = Pi / 2.0;
inline constexpr double PiOver4 = Pi / 4.0;
inline constexpr double SqrtPi = 1.77245385090551602730;

inline constexpr double degrees(double radians) { return radians * (180.0 / Pi); }
inline constexpr double radians(double degrees) { return degrees * (Pi / 180.0); }

template <typename T> constexpr T sqr(const T& x) { return x * x; }

// Branches instead of std::max/std::clamp so that Jets keep their derivative on the
// selected side (std::max<Jet> would also work, but would pick an arbitrary side at ties).
template <typename T> T clampTo(const T& x, double lo, double hi) {
  if (x < T(lo)) return T(lo);
  if (x > T(hi)) return T(hi);
  return x;
}

// sqrt(max(x, 0)). At x <= 0 returns 0 with zero derivative (not sqrt's infinite slope).
template <typename T> T safeSqrt(const T& x) {
  using std::sqrt;
  return x > T(0) ? sqrt(x) : T(0);
}

// acos/asin with the argument clamped to [-1, 1]; round-off just outside the domain
// would otherwise give NaN.
template <typename T> T safeAcos(const T& x) {
  using std::acos;
  return acos(clampTo(x, -1.0, 1.0));
}
template <typename T> T safeAsin(const T& x) {
  using std::asin;
  return asin(clampTo(x, -1.0, 1.0));
}

// Relative difference |a - b| / max(|a|, |b|), 0 when both are 0: what the consistency checks
// compare against their tolerances.
inline double relativeDifference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

inline bool isFinite(const Vec3d& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace scatterlab
