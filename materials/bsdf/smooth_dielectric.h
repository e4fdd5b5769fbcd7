// Smooth dielectric interface (glass, water): delta reflection and delta refraction with the
// exact Fresnel reflectance R (fresnel.h), sampled with probability R and T = 1 - R
// (pbrt-v4 DielectricBxDF, smooth case; Veach 1997 section 5.2 for the transport modes).
//
//   reflection:  f = R delta(wo - mirror(wi)) / |cos wo|,             weight 1
//   refraction:  f = T delta(wo - refract(wi)) / |cos wo| * s,         weight s
//   s = 1 for importance, 1 / etaRel^2 for radiance, etaRel = n(wo) / n(wi)
//
// Radiance is not conserved across a refraction: the refracted beam's solid angle shrinks by
// etaRel^2, so radiance grows by etaRel^2 while the power (importance transport, weight T)
// is conserved. Both sides are physical: wi.z < 0 is light inside the medium, where the
// relative index is 1 / eta and total internal reflection (R = 1) happens beyond the critical
// angle. Lossless: R + T = 1 at every wi (importance mode).
//
// Placed on a surface, it must not be mirrored by `Bsdf`'s two-sided flip (construct the Bsdf
// with twoSided = false): the side of wi is what tells inside from outside.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/refraction.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

class SmoothDielectricBsdf final : public BsdfModel {
 public:
  // eta: the index below the surface relative to above (> 0). eta = 1 is an index-matched,
  // invisible interface: R = 0 and every sample passes straight through with weight 1.
  explicit SmoothDielectricBsdf(double eta) : eta_(eta) {}

  Rgb eval(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return Rgb(0.0);
  }
  double pdf(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return 0.0;
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d&,
                                   TransportMode mode = TransportMode::Radiance) const override {
    if (wi.z == 0 || !std::isfinite(wi.z)) return std::nullopt;
    const double r = reflectance(wi.z);
    // r = 1 (total internal reflection) always reflects: transmission has probability 0.
    if (chooseLobe(uLobe, r).lobe == 0)
      return BsdfSample{Vec3d(-wi.x, -wi.y, wi.z), Rgb(1.0), r, LobeFlags::SpecularReflection, 1.0};
    const std::optional<Refraction> t = refract(wi, Vec3d(0, 0, 1), eta_);
    // Refraction fails only under total internal reflection, where r = 1; a rounding
    // disagreement between the two tests there loses a sample instead of producing one.
    if (!t) return std::nullopt;
    const double scale = mode == TransportMode::Radiance ? 1.0 / (t->etaRel * t->etaRel) : 1.0;
    return BsdfSample{t->w, Rgb(scale), 1.0 - r, LobeFlags::SpecularTransmission, t->etaRel};
  }

  LobeFlags flags() const override { return LobeFlags::SpecularReflection | LobeFlags::SpecularTransmission; }
  bool isLossless() const override { return true; }
  double interiorIndex() const override { return eta_; }

  // Fresnel reflectance for light arriving at cos theta_i (negative: from inside).
  double reflectance(double cosThetaI) const { return fresnelDielectric(cosThetaI, eta_); }
  double eta() const { return eta_; }

 private:
  double eta_;
};

struct MaterialModel;

// The material registry's "dielectric" model (materials/registry/model_list.h).
MaterialModel dielectricModel();

}  // namespace scatterlab
