// Rough conductor: single-scattering microfacet reflection with the exact conductor Fresnel
// term (Cook & Torrance 1982; Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces", eq. 20), Smith height-correlated masking-shadowing (Heitz 2014 eq. 99).
// Energy scattered more than once between microfacets is lost, unless the Kulla-Conty
// compensation lobe (kulla_conty.h) is added: then a conductor with F = 1 reflects everything.
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/fresnel_average.h"
#include "materials/bsdf/kulla_conty.h"
#include "materials/bsdf/microfacet.h"
#include "materials/bsdf/microfacet_type.h"
#include "materials/bsdf/white_microfacet_albedo.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

// Which density sample() draws microfacet normals from: the normals visible from wi (low
// variance, the default), or D(m) cos theta_m (the classic scheme, kept so the test kit can
// compare sampler efficiency).
enum class MicrofacetSampling { Visible, Classic };

// f(wi, wo) = D(h) F(wi.h) G2(wi, wo) / (4 cos_i cos_o), h = normalize(wi + wo) (Walter et al.
// 2007 eq. 20), one-sided: 0 unless both directions are above the surface. Without the cosine
// of wo (bsdf.h conventions). The kernel shared by rendering (T = double) and fitting
// (T = ceres::Jet).
template <typename T, typename Distribution>
RgbT<T> microfacetConductorEval(const Distribution& distribution, const RgbT<T>& eta, const RgbT<T>& k,
                                const Vec3<T>& wi, const Vec3<T>& wo) {
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return RgbT<T>(T(0));
  const Vec3<T> h = glm::normalize(wi + wo);
  const RgbT<T> fresnel = fresnelConductor(T(glm::dot(wi, h)), eta, k);
  return fresnel * (distribution.D(h) * distribution.G2(wi, wo) / (T(4) * wi.z * wo.z));
}

template <typename Distribution> class MicrofacetConductorBsdf final : public BsdfModel {
 public:
  // With MultipleScattering::KullaConty both roughnesses must be in (0, 1], the range of the
  // albedo tables (std::invalid_argument otherwise).
  MicrofacetConductorBsdf(const Distribution& distribution, const Rgb& eta, const Rgb& k,
                          MicrofacetSampling sampling = MicrofacetSampling::Visible,
                          MultipleScattering multipleScattering = MultipleScattering::None)
      : distribution_(distribution), eta_(eta), k_(k), sampling_(sampling) {
    if (multipleScattering == MultipleScattering::KullaConty) {
      lobe_ = std::make_shared<const KullaContyLobe>(WhiteMicrofacetAlbedo::of(distribution_));
      const Rgb fresnelAverage = conductorFresnelAverage(eta_, k_);
      fresnelMs_ = kullaContyFresnel(fresnelAverage, lobe_->albedo().average());
      // F = 1 to round-off (a perfect conductor, k -> infinity): nothing is absorbed, and
      // single scattering plus the lobe returns everything.
      constexpr double WhiteTolerance = 1e-9;
      lossless_ = std::min({fresnelAverage.x, fresnelAverage.y, fresnelAverage.z}) >= 1.0 - WhiteTolerance;
    }
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!lobe_) return microfacetConductorEval<double>(distribution_, eta_, k_, wi, wo);
    return compensatedEval(wi, wo, lobe_->albedo().loss(wi));
  }

  // Without compensation, the density of the sampled microfacet normal's reflection. With it,
  // the mixture that sample() draws: the single-scattering lobe with probability E(wi), the
  // lobes' shares of the light for F = 1, and the compensation lobe's sampler otherwise.
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!lobe_) return singlePdf(wi, wo);
    return compensatedPdf(wi, wo, lobe_->albedo()(wi));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    if (lobe_) return sampleCompensated(wi, uLobe, u);
    const Vec3d wo = reflect(wi, sampleNormal(wi, u));
    if (!(wo.z > 0)) return std::nullopt;
    // Everything below is computed from (wi, wo) exactly as eval() and pdf() compute it, so
    // that the sample's pdf is bit-identical to pdf(wi, wo).
    const Vec3d h = glm::normalize(wi + wo);
    const double density = reflectedPdf(wi, wo, h);
    if (!(density > 0)) return std::nullopt;
    const double cosIH = glm::dot(wi, h);
    // weight = f cos_o / pdf with D and cos_o cancelled (cos_i too for visible sampling), so it
    // stays finite where D or cos_i is tiny: F G2 / G1(wi) for visible normals (Heitz &
    // d'Eon 2014), F G2 (wo.h) / (cos_i h.z) for the classic scheme (Walter et al. 2007 eq. 41).
    const double shadowing = sampling_ == MicrofacetSampling::Visible
                                 ? distribution_.G2(wi, wo) / distribution_.G1(wi)
                                 : distribution_.G2(wi, wo) * cosIH / (wi.z * h.z);
    const Rgb weight = fresnelConductor(cosIH, eta_, k_) * shadowing;
    return BsdfSample{wo, weight, density, LobeFlags::GlossyReflection, 1.0};
  }

  LobeFlags flags() const override {
    return lobe_ ? LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection : LobeFlags::GlossyReflection;
  }
  // Only a compensated conductor with F = 1 loses nothing.
  bool isLossless() const override { return lossless_; }

  const Distribution& distribution() const { return distribution_; }
  const Rgb& eta() const { return eta_; }
  const Rgb& k() const { return k_; }
  MicrofacetSampling sampling() const { return sampling_; }
  MultipleScattering multipleScattering() const {
    return lobe_ ? MultipleScattering::KullaConty : MultipleScattering::None;
  }
  // The compensation lobe (F = 1) and F_ms; null / 0 without compensation.
  const KullaContyLobe* compensationLobe() const { return lobe_.get(); }
  const Rgb& multipleScatteringFresnel() const { return fresnelMs_; }

 private:
  Vec3d sampleNormal(const Vec3d& wi, const Vec2d& u) const {
    return sampling_ == MicrofacetSampling::Visible ? distribution_.sampleVisible(wi, u)
                                                    : distribution_.sampleClassic(u);
  }

  double singlePdf(const Vec3d& wi, const Vec3d& wo) const {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return reflectedPdf(wi, wo, glm::normalize(wi + wo));
  }
  // eval() and pdf() with compensation, given E(wi) (a table lookup, done once per sample).
  Rgb compensatedEval(const Vec3d& wi, const Vec3d& wo, double lossI) const {
    const Rgb single = microfacetConductorEval<double>(distribution_, eta_, k_, wi, wo);
    if (!(wi.z > 0) || !(wo.z > 0)) return single;
    const KullaContyLobe& lobe = *lobe_;
    return single + fresnelMs_ * kullaContyLobe(lossI, lobe.albedo().loss(wo), lobe.albedo().averageLoss());
  }
  double compensatedPdf(const Vec3d& wi, const Vec3d& wo, double albedoI) const {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return albedoI * singlePdf(wi, wo) + (1.0 - albedoI) * lobe_->pdf(wo);
  }

  // One lobe chosen by uLobe with the probabilities of pdf(); the weight is the mixture's
  // f cos / pdf, computed as eval() and pdf() compute them.
  std::optional<BsdfSample> sampleCompensated(const Vec3d& wi, double uLobe, const Vec2d& u) const {
    const double albedoI = lobe_->albedo()(wi);
    const bool single = chooseLobe(uLobe, albedoI).lobe == 0;
    std::optional<Vec3d> wo = single ? reflect(wi, sampleNormal(wi, u)) : lobe_->sample(u);
    if (!wo || !(wo->z > 0)) return std::nullopt;
    const double density = compensatedPdf(wi, *wo, albedoI);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{*wo, compensatedEval(wi, *wo, 1.0 - albedoI) * (wo->z / density), density,
                      single ? LobeFlags::GlossyReflection : LobeFlags::DiffuseReflection, 1.0};
  }

  // Density of wo = reflect(wi, h): the density of h times the Jacobian of the reflection,
  // d omega_h / d omega_o = 1 / (4 |wo.h|) (Walter et al. 2007 eq. 14).
  double reflectedPdf(const Vec3d& wi, const Vec3d& wo, const Vec3d& h) const {
    const double normalDensity = sampling_ == MicrofacetSampling::Visible ? distribution_.pdfVisible(wi, h)
                                                                          : distribution_.pdfClassic(h);
    return normalDensity / (4.0 * std::abs(glm::dot(wo, h)));
  }

  Distribution distribution_;
  Rgb eta_, k_;
  MicrofacetSampling sampling_;
  std::shared_ptr<const KullaContyLobe> lobe_;  // set with compensation
  Rgb fresnelMs_{0.0};
  bool lossless_ = false;
};

// The conductor for the registry. alphaX and alphaY must be positive and finite, and at most 1
// with compensation (std::invalid_argument otherwise; the registry reports the allowed range to
// the user).
std::unique_ptr<BsdfModel> makeMicrofacetConductor(
    MicrofacetType type, double alphaX, double alphaY, const Rgb& eta, const Rgb& k,
    MicrofacetSampling sampling = MicrofacetSampling::Visible,
    MultipleScattering multipleScattering = MultipleScattering::None);

struct MaterialModel;

// The material registry's "conductor" model (materials/registry/model_list.h).
MaterialModel conductorModel();

}  // namespace scatterlab
