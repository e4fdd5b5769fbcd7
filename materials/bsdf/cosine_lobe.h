// Pieces shared by the cosine-power lobe models (Phong, Blinn-Phong, Lafortune; Oren-Nayar
// uses only the diffuse/glossy mixture): the normalised lobe (n+2)/(2 pi) cos^n, the lobe
// density (n+1)/(2 pi) cos^n and its exact sampler, and the choice between a diffuse and a
// glossy component by a selection probability.
#pragma once

#include <optional>

#include "materials/bsdf/bsdf.h"
#include "materials/core/frame.h"
#include "materials/core/warp.h"

namespace scatterlab {

// max(c, 0)^n with 0 for c <= 0 (also at n = 0, so that the lobe is one-sided about its
// axis); pow is only called at c > 0, where value and derivative are finite for Jets.
template <typename T, typename C> T clampedCosinePower(const C& c, const T& n) {
  using std::pow;
  if (!(c > C(0))) return T(0);
  return pow(T(c), n);
}

// The normalised lobe (n+2)/(2 pi) max(c, 0)^n: its projected-solid-angle integral about
// the normal is 1 (Lafortune & Willems 1994, eq. 7).
template <typename T, typename C> T normalizedCosinePower(const C& c, const T& n) {
  return (n + T(2)) * T(Inv2Pi) * clampedCosinePower(c, n);
}

// The density (n+1)/(2 pi) max(cos, 0)^n about an axis, per solid angle.
inline double cosinePowerPdf(double cosAxis, double n) {
  return (n + 1.0) * Inv2Pi * clampedCosinePower(cosAxis, n);
}

// A direction about +z with density cosinePowerPdf(w.z, n): cos = u0^(1/(n+1)), phi = 2 pi u1.
inline Vec3d sampleCosinePower(const Vec2d& u, double n) {
  const double cosTheta = std::pow(u.x, 1.0 / (n + 1.0));
  const double sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
  const double phi = 2.0 * Pi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}
// The same about a unit axis.
inline Vec3d sampleCosinePowerAbout(const Vec3d& axis, const Vec2d& u, double n) {
  return Framed::fromNormal(axis).toWorld(sampleCosinePower(u, n));
}

inline double channelMean(const Rgb& c) { return (c.x + c.y + c.z) / 3.0; }

// Probability of sampling the glossy part of kd/pi + glossy: mean(ks) / (mean(kd) + mean(ks)),
// 1/2 when both are black (f = 0; any sampler is correct then).
inline double glossySelectionProbability(const Rgb& kd, const Rgb& ks) {
  const double d = channelMean(kd), s = channelMean(ks);
  return d + s > 0 ? s / (d + s) : 0.5;
}

// Completes a sample from its direction: fails below the horizon or at zero density,
// weight = f cos / pdf otherwise.
template <typename Model>
std::optional<BsdfSample> finishSample(const Model& model, const Vec3d& wi, const Vec3d& wo, LobeFlags lobe) {
  if (!(wo.z > 0)) return std::nullopt;
  const double pdf = model.pdf(wi, wo);
  if (!(pdf > 0)) return std::nullopt;
  return BsdfSample{wo, model.eval(wi, wo) * (wo.z / pdf), pdf, lobe, 1.0};
}

// A reflection model sampled cosine-weighted about the normal, whatever its f: pdf cos / pi and
// its exact sampler, weight f pi. Derived (final) supplies eval; the exit BSDF of the subsurface
// renderer and the far-field BRDF of a subsurface material are such models.
template <typename Derived> class CosineSampledReflection : public BsdfModel {
 public:
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0 || wo.z <= 0) return 0.0;
    return cosineHemispherePdf(wo.z);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0) return std::nullopt;
    return finishSample(static_cast<const Derived&>(*this), wi, sampleCosineHemisphere(u),
                        LobeFlags::DiffuseReflection);
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection; }
};

}  // namespace scatterlab
