// Rusinkiewicz's half/difference coordinates of a reflection pair (S. Rusinkiewicz 1998, "A New
// Change of Variables for Efficient BRDF Representation", EGWR, sec. 3): h = normalize(wi + wo)
// at (theta_h, phi_h); the difference vector d is wi seen from a frame in which h is the
// pole, d = R_y(-theta_h) R_z(-phi_h) wi, at (theta_d, phi_d). The MERL layout (Matusik et al.
// 2003) tabulates isotropic BRDFs over (theta_h, theta_d, phi_d); phi_h is dropped.
//
// Swapping wi and wo keeps h and maps d to (-d.x, -d.y, d.z): theta_d stays, phi_d moves by
// pi. That is why a reciprocal BRDF needs phi_d only modulo pi (merl_format.h folds it).
#pragma once

#include <utility>

#include "materials/core/spherical.h"

namespace scatterlab {

struct HalfDiff {
  double thetaHalf = 0, phiHalf = 0;  // h; phiHalf in (-pi, pi]
  double thetaDiff = 0, phiDiff = 0;  // d; phiDiff in (-pi, pi], not folded
};

// wi, wo above the surface (wi + wo != 0). theta_h comes from atan2(|h_xy|, h_z), equal to
// acos(h.z) but without acos's loss of precision next to the pole, where the MERL theta_h axis
// is densest. At the pole phi_h is undefined and taken as 0 (any choice is exact for an
// isotropic BRDF at theta_h = 0).
// phi_h (one atan2) only when asked for: the isotropic MERL table has no use for it.
inline HalfDiff halfDiffFromDirections(const Vec3d& wi, const Vec3d& wo, bool withPhiHalf = true) {
  const Vec3d h = glm::normalize(wi + wo);
  const double sinThetaH = std::sqrt(h.x * h.x + h.y * h.y);
  const double cosThetaH = h.z;
  const double cosPhiH = sinThetaH > 0 ? h.x / sinThetaH : 1.0;
  const double sinPhiH = sinThetaH > 0 ? h.y / sinThetaH : 0.0;
  // R_z(-phi_h) wi, then R_y(-theta_h).
  const double x1 = wi.x * cosPhiH + wi.y * sinPhiH;
  const double y1 = -wi.x * sinPhiH + wi.y * cosPhiH;
  const double z1 = wi.z;
  const Vec3d d(x1 * cosThetaH - z1 * sinThetaH, y1, x1 * sinThetaH + z1 * cosThetaH);
  HalfDiff hd;
  hd.thetaHalf = std::atan2(sinThetaH, cosThetaH);
  hd.phiHalf = withPhiHalf && sinThetaH > 0 ? std::atan2(h.y, h.x) : 0.0;
  hd.thetaDiff = std::atan2(std::sqrt(d.x * d.x + d.y * d.y), d.z);
  hd.phiDiff = std::atan2(d.y, d.x);
  return hd;
}

// The inverse: (wi, wo) with wi = R_z(phi_h) R_y(theta_h) d and wo its mirror about h.
inline std::pair<Vec3d, Vec3d> directionsFromHalfDiff(double thetaHalf, double phiHalf, double thetaDiff,
                                                      double phiDiff) {
  const Vec3d d = sphericalDirection(std::sin(thetaDiff), std::cos(thetaDiff), phiDiff);
  const double cosT = std::cos(thetaHalf), sinT = std::sin(thetaHalf);
  const double cosP = std::cos(phiHalf), sinP = std::sin(phiHalf);
  const auto toWorld = [&](const Vec3d& v) {
    const double x1 = v.x * cosT + v.z * sinT, z1 = -v.x * sinT + v.z * cosT;  // R_y(theta_h)
    return Vec3d(x1 * cosP - v.y * sinP, x1 * sinP + v.y * cosP, z1);          // R_z(phi_h)
  };
  return {toWorld(d), toWorld(Vec3d(-d.x, -d.y, d.z))};
}

// cos of the polar angles of wi and wo at (theta_h, theta_d, phi_d), without building them:
// the z components of R_y(theta_h) (+-d.x, +-d.y, d.z). Both positive iff the pair is a
// reflection above the surface.
inline std::pair<double, double> polarCosinesFromHalfDiff(double thetaHalf, double thetaDiff,
                                                          double phiDiff) {
  const double a = std::cos(thetaDiff) * std::cos(thetaHalf);
  const double b = std::sin(thetaDiff) * std::cos(phiDiff) * std::sin(thetaHalf);
  return {a - b, a + b};
}

}  // namespace scatterlab
