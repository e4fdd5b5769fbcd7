// Smooth conductor: a perfect mirror whose reflectance is the exact Fresnel term of a metal
// with complex index eta + i k per RGB channel (fresnel.h; pbrt-v4 ConductorBxDF in its
// smooth limit). A delta lobe: f = F(cos_i) delta(wo - mirror(wi)) / |cos wo|, so eval and
// pdf are 0 for every pair and sample() returns the mirror direction with probability 1 and
// weight F. One-sided, like every reflection-only model: nothing for wi.z <= 0.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/fresnel_average.h"

namespace scatterlab {

class SmoothConductorBsdf final : public BsdfModel {
 public:
  SmoothConductorBsdf(const Rgb& eta, const Rgb& k)
      : eta_(eta), k_(k), lossless_(isPerfectConductor(eta, k)) {}

  Rgb eval(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return Rgb(0.0);
  }
  double pdf(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return 0.0;
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d&,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    return BsdfSample{Vec3d(-wi.x, -wi.y, wi.z), reflectance(wi.z), 1.0, LobeFlags::SpecularReflection, 1.0};
  }

  LobeFlags flags() const override { return LobeFlags::SpecularReflection; }
  // A metal absorbs what it does not reflect; F = 1 only in the limit k -> infinity, a perfect
  // conductor (fresnel_average.h), which is lossless to that limit's tolerance.
  bool isLossless() const override { return lossless_; }
  double losslessAccuracy() const override { return PerfectConductorTolerance; }

  // The mirror's reflectance at incidence cos theta_i: the sample weight.
  Rgb reflectance(double cosThetaI) const { return fresnelConductor(cosThetaI, eta_, k_); }
  const Rgb& eta() const { return eta_; }
  const Rgb& k() const { return k_; }

 private:
  Rgb eta_, k_;
  bool lossless_;
};

struct MaterialModel;

// The material registry's "smooth-conductor" model (materials/registry/model_list.h).
MaterialModel smoothConductorModel();

}  // namespace scatterlab
