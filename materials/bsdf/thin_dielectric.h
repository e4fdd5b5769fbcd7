// Thin dielectric sheet (a window pane, a soap film without interference): two parallel
// smooth interfaces with the same medium on both sides, collapsed to one surface
// (pbrt-v4 ThinDielectricBxDF; Pharr, Jakob & Humphreys 2023, Physically Based Rendering, 4th
// ed., section 9.5, "Dielectric BSDF").
//
// Light bounces between the two interfaces; summing the geometric series of internal
// reflections, each with the single-interface Fresnel reflectance R and T = 1 - R, gives
//   R' = R + T^2 R (1 + R^2 + R^4 + ...) = R + T^2 R / (1 - R^2),   T' = 1 - R'.
// The internal bounces leave parallel to the entry ray (the sheet has no thickness here),
// so reflection is the mirror direction and transmission goes straight through, wo = -wi,
// without refraction: the medium on both sides is the same, so no radiance scaling either
// (the transport modes agree and interiorIndex() is 1). Lossless, two-sided, symmetric.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

class ThinDielectricBsdf final : public BsdfModel {
 public:
  // eta: the sheet's index relative to the surrounding medium (> 0).
  explicit ThinDielectricBsdf(double eta) : eta_(eta) {}

  Rgb eval(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return Rgb(0.0);
  }
  double pdf(const Vec3d&, const Vec3d&, TransportMode = TransportMode::Radiance) const override {
    return 0.0;
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d&,
                                   TransportMode = TransportMode::Radiance) const override {
    if (wi.z == 0 || !std::isfinite(wi.z)) return std::nullopt;
    const double r = reflectance(wi.z);
    if (chooseLobe(uLobe, r).lobe == 0)
      return BsdfSample{Vec3d(-wi.x, -wi.y, wi.z), Rgb(1.0), r, LobeFlags::SpecularReflection, 1.0};
    return BsdfSample{-wi, Rgb(1.0), 1.0 - r, LobeFlags::SpecularTransmission, 1.0};
  }

  LobeFlags flags() const override { return LobeFlags::SpecularReflection | LobeFlags::SpecularTransmission; }
  bool isLossless() const override { return true; }

  // R' of the sheet for light arriving at cos theta_i (either side: the sheet is symmetric).
  double reflectance(double cosThetaI) const {
    const double r = fresnelDielectric(std::abs(cosThetaI), eta_);
    // r = 1 only at grazing incidence, where nothing enters the sheet (and 1 - r^2 = 0).
    if (!(r < 1.0)) return 1.0;
    const double t = 1.0 - r;
    return r + t * t * r / (1.0 - r * r);
  }
  double eta() const { return eta_; }

 private:
  double eta_;
};

struct MaterialModel;

// The material registry's "thin-dielectric" model (materials/registry/model_list.h).
MaterialModel thinDielectricModel();

}  // namespace scatterlab
