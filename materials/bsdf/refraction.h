// Refraction through an interface between two dielectrics: Snell's law, the generalised half
// vector of a refraction pair, and the Jacobian from the half vector to the refracted
// direction (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces",
// eq. 16-17). Shared by the smooth and rough dielectrics.
//
// Index convention: `eta` is the index below the surface (z < 0) relative to the index above,
// as BsdfModel::interiorIndex(). The relative index across one crossing,
// n(destination) / n(origin), is written etaRel.
#pragma once

#include <optional>

#include "materials/core/spherical.h"

namespace scatterlab {

// n(wo) / n(wi) for a pair on opposite sides of the surface, interior index `eta`; 1 for a
// reflection pair (both on one side).
template <typename T> T relativeIndex(const Vec3<T>& wi, const Vec3<T>& wo, const T& eta) {
  if (wi.z * wo.z > T(0)) return T(1);
  return wi.z > T(0) ? eta : T(1) / eta;
}

struct Refraction {
  Vec3d w;        // the refracted direction, pointing away from the surface on the other side
  double etaRel;  // n(w) / n(incident side)
};

// Snell's law about the normal n (pbrt-v4 Refract): w points away from the surface, on either
// side of n; eta = n(behind n) / n(in front of n). Nothing under total internal reflection.
inline std::optional<Refraction> refract(const Vec3d& w, Vec3d n, double eta) {
  double cosI = glm::dot(n, w);
  if (cosI < 0) {  // w is behind n: the media swap
    eta = 1.0 / eta;
    cosI = -cosI;
    n = -n;
  }
  const double sin2T = std::max(0.0, 1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return std::nullopt;
  const double cosT = std::sqrt(1.0 - sin2T);
  // Tangential part scaled by 1/eta (Snell), normal part -cosT: a unit vector by construction.
  return Refraction{-w / eta + (cosI / eta - cosT) * n, eta};
}

// The generalised half vector of Walter et al. 2007 eq. 16, h proportional to
// n_i wi + n_o wo = n_i (wi + etaRel wo), turned to the upper hemisphere (microfacet normals
// point up). For a reflection pair etaRel = 1 and this is the usual half vector. The zero
// vector when the sum vanishes (only possible for etaRel = 1 and wo = -wi).
template <typename T> Vec3<T> generalizedHalfVector(const Vec3<T>& wi, const Vec3<T>& wo, const T& etaRel) {
  using std::sqrt;
  const Vec3<T> sum = wi + wo * etaRel;
  const T length2 = glm::dot(sum, sum);
  if (!(length2 > T(0))) return Vec3<T>(T(0), T(0), T(0));
  return sum * ((sum.z < T(0) ? T(-1) : T(1)) / sqrt(length2));
}

// d omega_h / d omega_o for wo refracted from wi about h: n_o^2 |wo.h| / (n_i wi.h + n_o wo.h)^2
// (Walter et al. 2007 eq. 17), written with etaRel = n_o / n_i. The denominator vanishes only
// when etaRel = 1 (Snell's law with cos_i = etaRel cos_t and sin_i = etaRel sin_t).
template <typename T>
T refractionJacobian(const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& h, const T& etaRel) {
  using std::abs;
  const T cosOH = glm::dot(wo, h);
  const T denominator = glm::dot(wi, h) / etaRel + cosOH;
  return abs(cosOH) / (denominator * denominator);
}

}  // namespace scatterlab
