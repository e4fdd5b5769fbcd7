// Sample warps from [0,1)^2 to common domains, each as a triplet (pbrt-v4 style):
//   sampleX(u) -> point, xPdf(...) -> density of that point w.r.t. the domain's measure
//   (area for the disk, solid angle for directions), invertX(point) -> u.
// invert(sample(u)) == u is checked for every warp in tests/materials/core/warp_test.cpp,
// and each sampler passes the chi-square kit against its pdf.
#pragma once

#include "materials/core/spherical.h"

namespace scatterlab {

// ---- Uniform sphere: z = 1 - 2 u0, phi = 2 pi u1 ----
inline Vec3d sampleUniformSphere(const Vec2d& u) {
  const double z = 1.0 - 2.0 * u.x;
  const double r = safeSqrt(1.0 - z * z);
  const double phi = 2.0 * Pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline double uniformSpherePdf() { return Inv4Pi; }
inline Vec2d invertUniformSphere(const Vec3d& w) {
  double phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2.0 * Pi;
  return {(1.0 - w.z) / 2.0, phi * Inv2Pi};
}

// ---- Uniform hemisphere (z >= 0): z = u0, phi = 2 pi u1 ----
inline Vec3d sampleUniformHemisphere(const Vec2d& u) {
  const double z = u.x;
  const double r = safeSqrt(1.0 - z * z);
  const double phi = 2.0 * Pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline double uniformHemispherePdf() { return Inv2Pi; }
inline Vec2d invertUniformHemisphere(const Vec3d& w) {
  double phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2.0 * Pi;
  return {w.z, phi * Inv2Pi};
}

// ---- Concentric disk: Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square".
// Area-preserving up to the constant 1/pi, and continuous, so stratification survives.
inline Vec2d sampleConcentricDisk(const Vec2d& u) {
  const Vec2d o = 2.0 * u - Vec2d(1.0);
  if (o.x == 0 && o.y == 0) return {0, 0};
  double r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = PiOver4 * (o.y / o.x);
  } else {
    r = o.y;
    theta = PiOver2 - PiOver4 * (o.x / o.y);
  }
  return r * Vec2d(std::cos(theta), std::sin(theta));
}
inline double concentricDiskPdf() { return InvPi; }
inline Vec2d invertConcentricDisk(const Vec2d& p) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  if (r == 0) return {0.5, 0.5};
  double phi = std::atan2(p.y, p.x);  // (-pi, pi]
  // Undo the four wedges of the forward map; r keeps the sign of o.x (|o.x| > |o.y| wedges)
  // or of o.y (the others).
  if (phi < -PiOver4) phi += 2.0 * Pi;  // now in [-pi/4, 7pi/4)
  double a, b;                          // (o.x, o.y)
  if (phi < PiOver4) {                  // right wedge: r = o.x > 0, theta = pi/4 * o.y / o.x
    a = r;
    b = phi * a / PiOver4;
  } else if (phi < 3.0 * PiOver4) {  // top: r = o.y > 0, theta = pi/2 - pi/4 * o.x / o.y
    b = r;
    a = (PiOver2 - phi) * b / PiOver4;
  } else if (phi < 5.0 * PiOver4) {  // left: r = o.x < 0, theta - pi = pi/4 * o.y / o.x
    a = -r;
    b = (phi - Pi) * a / PiOver4;
  } else {  // bottom: r = o.y < 0, theta = pi/2 - pi/4 * o.x/o.y + pi
    b = -r;
    a = (3.0 * PiOver2 - phi) * b / PiOver4;
  }
  return {(a + 1.0) / 2.0, (b + 1.0) / 2.0};
}

// ---- Cosine-weighted hemisphere: Malley's method (project the concentric disk up) ----
inline Vec3d sampleCosineHemisphere(const Vec2d& u) {
  const Vec2d d = sampleConcentricDisk(u);
  const double z = safeSqrt(1.0 - d.x * d.x - d.y * d.y);
  return {d.x, d.y, z};
}
inline double cosineHemispherePdf(double cosTheta) { return cosTheta > 0 ? cosTheta * InvPi : 0.0; }
inline Vec2d invertCosineHemisphere(const Vec3d& w) { return invertConcentricDisk({w.x, w.y}); }

// ---- Uniform cone around +z with half-angle acos(cosThetaMax) ----
inline Vec3d sampleUniformCone(const Vec2d& u, double cosThetaMax) {
  const double cosTheta = (1.0 - u.x) + u.x * cosThetaMax;
  const double sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
  const double phi = 2.0 * Pi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}
inline double uniformConePdf(double cosThetaMax) { return 1.0 / (2.0 * Pi * (1.0 - cosThetaMax)); }
inline Vec2d invertUniformCone(const Vec3d& w, double cosThetaMax) {
  const double u0 = (1.0 - w.z) / (1.0 - cosThetaMax);
  double phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2.0 * Pi;
  return {u0, phi * Inv2Pi};
}

}  // namespace scatterlab
