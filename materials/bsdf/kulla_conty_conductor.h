// A rough conductor with Kulla-Conty multiple-scattering compensation (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks", SIGGRAPH course): the single-scattering
// conductor of conductor.h plus the compensation lobe of kulla_conty.h coloured by F_ms,
//   f(wi, wo) = f_single(wi, wo) + F_ms f_ms(wi, wo).
// A composition: the single-scattering model is used as it is, so what the kit proves about it
// holds here too. A perfect conductor (F = 1) reflects everything, to the albedo tables' error
// (losslessAccuracy()).
//
// Sampling: the single-scattering lobe with probability E(wi) (its share of the light for
// F = 1), the compensation lobe's sampler otherwise; pdf() is that mixture exactly, and a
// sample's weight is f cos / pdf of the mixture, computed as eval() and pdf() compute them.
#pragma once

#include <memory>
#include <optional>

#include "materials/bsdf/conductor.h"
#include "materials/bsdf/fresnel_average.h"
#include "materials/bsdf/kulla_conty.h"
#include "materials/bsdf/white_microfacet_albedo.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

template <typename Distribution> class KullaContyConductorBsdf final : public BsdfModel {
 public:
  // Both roughnesses must be in (0, 1], the range of the albedo tables (std::invalid_argument
  // otherwise).
  KullaContyConductorBsdf(const Distribution& distribution, const Rgb& eta, const Rgb& k,
                          MicrofacetSampling sampling = MicrofacetSampling::Visible)
      : single_(distribution, eta, k, sampling),
        lobe_(std::make_shared<const KullaContyLobe>(WhiteMicrofacetAlbedo::of(distribution))),
        fresnelMs_(kullaContyFresnel(conductorFresnelAverage(eta, k), lobe_->albedo().average())),
        lossless_(isPerfectConductor(eta, k)) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return evalGivenLoss(wi, wo, lobe_->albedo().loss(wi));
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return pdfGivenAlbedo(wi, wo, lobe_->albedo()(wi));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    const double albedoI = lobe_->albedo()(wi);  // one table lookup per sample
    const bool single = chooseLobe(uLobe, albedoI).lobe == 0;
    const std::optional<Vec3d> wo = single ? single_.sampleDirection(wi, u) : lobe_->sample(u);
    if (!wo || !(wo->z > 0)) return std::nullopt;
    const double density = pdfGivenAlbedo(wi, *wo, albedoI);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{*wo, evalGivenLoss(wi, *wo, 1.0 - albedoI) * (wo->z / density), density,
                      single ? LobeFlags::GlossyReflection : LobeFlags::DiffuseReflection, 1.0};
  }

  LobeFlags flags() const override { return LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection; }
  // Only a perfect conductor loses nothing.
  bool isLossless() const override { return lossless_; }
  // The albedo tables' interpolation error in E(wi) and E_avg, which the compensation lobe
  // inherits (measured against direct quadrature by KullaContyFurnace in
  // tests/materials/bsdf/kulla_conty_test.cpp over alpha 0.001..1): 2e-4 on the isotropic
  // tables; an anisotropic pair reads the isotropic table at its projected roughness, up to
  // 4e-3 off near grazing (alpha 0.05 x 0.8), bounded here by 5e-3.
  double losslessAccuracy() const override { return single_.distribution().isotropic() ? 2e-4 : 5e-3; }

  const MicrofacetConductorBsdf<Distribution>& singleScattering() const { return single_; }
  const KullaContyLobe& compensationLobe() const { return *lobe_; }
  const Rgb& multipleScatteringFresnel() const { return fresnelMs_; }

 private:
  // eval() given 1 - E(wi) and pdf() given E(wi): a sample reads the table once.
  Rgb evalGivenLoss(const Vec3d& wi, const Vec3d& wo, double lossI) const {
    const Rgb single = single_.eval(wi, wo);
    if (!(wi.z > 0) || !(wo.z > 0)) return single;
    const WhiteMicrofacetAlbedo& albedo = lobe_->albedo();
    return single + fresnelMs_ * kullaContyLobe(lossI, albedo.loss(wo), albedo.averageLoss());
  }
  double pdfGivenAlbedo(const Vec3d& wi, const Vec3d& wo, double albedoI) const {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return albedoI * single_.pdf(wi, wo) + (1.0 - albedoI) * lobe_->pdf(wo);
  }

  MicrofacetConductorBsdf<Distribution> single_;
  std::shared_ptr<const KullaContyLobe> lobe_;
  Rgb fresnelMs_;
  bool lossless_;
};

}  // namespace scatterlab
