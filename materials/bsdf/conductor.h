// Rough conductor: single-scattering microfacet reflection with the exact conductor Fresnel
// term (Cook & Torrance 1982; Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces", eq. 20), Smith height-correlated masking-shadowing (Heitz 2014 eq. 99).
// Energy scattered more than once between microfacets is lost; kulla_conty_conductor.h adds
// the Kulla-Conty compensation lobe to this model, and then a conductor with F = 1 reflects
// everything.
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/kulla_conty.h"
#include "materials/bsdf/microfacet.h"
#include "materials/bsdf/microfacet_type.h"

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
  MicrofacetConductorBsdf(const Distribution& distribution, const Rgb& eta, const Rgb& k,
                          MicrofacetSampling sampling = MicrofacetSampling::Visible)
      : distribution_(distribution), eta_(eta), k_(k), sampling_(sampling) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return microfacetConductorEval<double>(distribution_, eta_, k_, wi, wo);
  }

  // The density of the sampled microfacet normal's reflection.
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return reflectedPdf(wi, wo, glm::normalize(wi + wo));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
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

  // The direction sample() draws, without its weight: for models that sample this lobe as
  // one of several (kulla_conty_conductor.h). May be below the surface.
  Vec3d sampleDirection(const Vec3d& wi, const Vec2d& u) const { return reflect(wi, sampleNormal(wi, u)); }

  LobeFlags flags() const override { return LobeFlags::GlossyReflection; }

  const Distribution& distribution() const { return distribution_; }
  const Rgb& eta() const { return eta_; }
  const Rgb& k() const { return k_; }
  MicrofacetSampling sampling() const { return sampling_; }

 private:
  Vec3d sampleNormal(const Vec3d& wi, const Vec2d& u) const {
    return sampling_ == MicrofacetSampling::Visible ? distribution_.sampleVisible(wi, u)
                                                    : distribution_.sampleClassic(u);
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
};

// The conductor for the registry: MicrofacetConductorBsdf, or with compensation
// KullaContyConductorBsdf (kulla_conty_conductor.h). alphaX and alphaY must be positive and
// finite, and at most 1 with compensation (std::invalid_argument otherwise; the registry
// reports the allowed range to the user).
std::unique_ptr<BsdfModel> makeMicrofacetConductor(
    MicrofacetType type, double alphaX, double alphaY, const Rgb& eta, const Rgb& k,
    MicrofacetSampling sampling = MicrofacetSampling::Visible,
    MultipleScattering multipleScattering = MultipleScattering::None);

struct MaterialModel;

// The material registry's "conductor" model (materials/registry/model_list.h).
MaterialModel conductorModel();

}  // namespace scatterlab
