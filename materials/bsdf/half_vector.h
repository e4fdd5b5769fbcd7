// What every half-vector sampled reflection lobe shares (Ward, Ashikhmin-Shirley,
// Cook-Torrance): the half vector of a reflection pair and the density of wo = reflect(wi, h)
// given the density of h, through the reflection Jacobian d omega_h / d omega_o = 1 / (4 |wo.h|)
// (Walter et al. 2007 eq. 14).
#pragma once

#include "materials/core/spherical.h"

namespace scatterlab {

// normalize(wi + wo); both directions above the surface, so h.z > 0.
template <typename T> Vec3<T> reflectionHalfVector(const Vec3<T>& wi, const Vec3<T>& wo) {
  return glm::normalize(wi + wo);
}

// Density per solid angle of wo = reflect(wi, h) when h has density `halfDensity`.
inline double reflectedDensity(double halfDensity, const Vec3d& wo, const Vec3d& h) {
  const double cosOH = std::abs(glm::dot(wo, h));
  return cosOH > 0 ? halfDensity / (4.0 * cosOH) : 0.0;
}

}  // namespace scatterlab
