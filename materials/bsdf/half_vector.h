// What every half-vector sampled reflection lobe shares (Ward, Ashikhmin-Shirley,
// Cook-Torrance): the half vector of a reflection pair and the density of wo = reflect(wi, h)
// given the density of h, through the reflection Jacobian d omega_h / d omega_o = 1 / (4 |wo.h|)
// (Walter et al. 2007 eq. 14).
#pragma once

#include <optional>

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

// Lobes that sample h from D(h) cos theta_h (the classic scheme) and reflect wi about it.
// The pdf of wo is computed from (wi, wo) alone, so sample() and pdf() agree to the last bit.
template <typename Distribution>
double classicReflectionPdf(const Distribution& distribution, const Vec3d& wi, const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
  const Vec3d h = reflectionHalfVector(wi, wo);
  return reflectedDensity(distribution.pdfClassic(h), wo, h);
}

struct ReflectionSample {
  Vec3d wo, h;
  double pdf;
};

// wo = reflect(wi, h), h ~ D(h) cos theta_h; nothing when wo is below the horizon or the
// density vanishes.
template <typename Distribution>
std::optional<ReflectionSample> sampleClassicReflection(const Distribution& distribution, const Vec3d& wi,
                                                        const Vec2d& u) {
  if (!(wi.z > 0)) return std::nullopt;
  const Vec3d wo = reflect(wi, distribution.sampleClassic(u));
  if (!(wo.z > 0)) return std::nullopt;
  const Vec3d h = reflectionHalfVector(wi, wo);
  const double pdf = reflectedDensity(distribution.pdfClassic(h), wo, h);
  if (!(pdf > 0)) return std::nullopt;
  return ReflectionSample{wo, h, pdf};
}

}  // namespace scatterlab
