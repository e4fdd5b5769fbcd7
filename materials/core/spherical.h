// Directions in the local shading frame (z = normal, x = tangent) and spherical coordinates.
// theta is measured from +z, phi from +x toward +y, in (-pi, pi].
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

template <typename T> T cosTheta(const Vec3<T>& w) { return w.z; }
template <typename T> T cos2Theta(const Vec3<T>& w) { return w.z * w.z; }
template <typename T> T absCosTheta(const Vec3<T>& w) {
  using std::abs;
  return abs(w.z);
}
template <typename T> T sin2Theta(const Vec3<T>& w) {
  const T s = T(1) - cos2Theta(w);
  return s > T(0) ? s : T(0);
}
template <typename T> T sinTheta(const Vec3<T>& w) { return safeSqrt(sin2Theta(w)); }
// tan^2 theta = sin^2/cos^2; infinite on the horizon (callers test cos first).
template <typename T> T tan2Theta(const Vec3<T>& w) { return sin2Theta(w) / cos2Theta(w); }

// cos phi and sin phi; phi is undefined at the pole, where (1, 0) is returned.
template <typename T> T cosPhi(const Vec3<T>& w) {
  const T s = sinTheta(w);
  return s == T(0) ? T(1) : clampTo(w.x / s, -1.0, 1.0);
}
template <typename T> T sinPhi(const Vec3<T>& w) {
  const T s = sinTheta(w);
  return s == T(0) ? T(0) : clampTo(w.y / s, -1.0, 1.0);
}

template <typename T> bool sameHemisphere(const Vec3<T>& a, const Vec3<T>& b) { return a.z * b.z > T(0); }

template <typename T> Vec3<T> sphericalDirection(T sinTheta, T cosTheta, T phi) {
  using std::cos;
  using std::sin;
  return {sinTheta * cos(phi), sinTheta * sin(phi), cosTheta};
}

inline double sphericalTheta(const Vec3d& w) { return safeAcos(w.z); }
inline double sphericalPhi(const Vec3d& w) { return std::atan2(w.y, w.x); }

// Mirror w about the normal n (both pointing away from the surface).
template <typename T> Vec3<T> reflect(const Vec3<T>& w, const Vec3<T>& n) {
  return T(2) * glm::dot(w, n) * n - w;
}

// The direction at (theta, phi) given in degrees; what the CLI's --wi-theta means.
inline Vec3d directionFromDegrees(double thetaDeg, double phiDeg) {
  const double t = radians(thetaDeg), p = radians(phiDeg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

}  // namespace scatterlab
