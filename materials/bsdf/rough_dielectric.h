// Rough dielectric BSDF: single-scattering microfacet reflection and refraction (Walter et
// al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 20 and 21) through
// the generalised half vector (eq. 16), with anisotropic GGX or Beckmann normals, exact
// dielectric Fresnel including total internal reflection, and Smith height-correlated
// masking-shadowing: Heitz 2014 eq. 99 for reflection, the Beta-function form for refraction
// (smith_transmission.h).
//
// Both sides are physical (wi.z < 0: light inside, relative index 1/eta). Radiance through a
// refraction carries 1 / etaRel^2 (Veach 1997 section 5.2), importance does not: eval, pdf
// and sample() take the TransportMode, and
//   eval(wi, wo, Radiance) = eval(wo, wi, Importance),
//   eval(wi, wo, Importance) / n(wo)^2 = eval(wo, wi, Importance) / n(wi)^2.
//
// Sampling (Walter et al. 2007 section 5.3 with visible normals, Heitz & d'Eon 2014): a normal
// m visible from wi, then reflection with probability F(wi.m), else refraction. The pdf is
// exact: the density of m (visible normals) times the lobe's probability times the Jacobian
// from m to wo (1 / (4 |wo.h|) or Walter eq. 17).
//
// Energy: light that scatters more than once among the microfacets is lost, so the published
// model is not lossless; rough_dielectric_albedo.h computes what it keeps. With
// MultipleScattering::KullaConty (isotropic roughness) the compensation lobe of
// rough_dielectric_multiscatter.h returns it, and the model is lossless in importance
// transport (isLossless() is true). It is then sampled as a mixture: single scattering with
// probability E_s(wi) (the table's single-scattering albedo at wi's side), the compensation
// lobe otherwise; the pdf is that mixture's, exactly.
#pragma once

#include <memory>
#include <stdexcept>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/half_vector.h"
#include "materials/bsdf/microfacet.h"
#include "materials/bsdf/microfacet_type.h"
#include "materials/bsdf/refraction.h"
#include "materials/bsdf/rough_dielectric_multiscatter.h"
#include "materials/bsdf/smith_transmission.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

// What eval() and pdf() both need of a pair (wi, wo). `eta` is the interior index (below
// relative to above). Not `valid` when no microfacet connects the pair: a direction on the
// horizon, or a facet h seen from behind by wi or wo (Walter et al. 2007 section 5.3: such
// configurations contribute 0). For a refraction pair, F(wi.h) = F(wo.h) (Fresnel
// transmittance is the same both ways); F is taken on the exterior side so that the pair and
// its reverse round identically. Built in place (no copies: see generalizedHalfVector).
template <typename T> struct DielectricPair {
  DielectricPair(const Vec3<T>& wi, const Vec3<T>& wo, const T& eta)
      : reflection(wi.z * wo.z > T(0)),
        etaRel(relativeIndex(wi, wo, eta)),
        h(generalizedHalfVector(wi, wo, etaRel)) {
    if (wi.z == T(0) || wo.z == T(0) || !(h.z > T(0))) return;
    cosIH = glm::dot(wi, h);
    cosOH = glm::dot(wo, h);
    if (!(cosIH * wi.z > T(0)) || !(cosOH * wo.z > T(0))) return;
    fresnel = fresnelDielectric(reflection || wi.z > T(0) ? cosIH : cosOH, eta);
    valid = true;
  }

  bool reflection;
  T etaRel;   // n(wo) / n(wi): 1 for reflection
  Vec3<T> h;  // the generalised half vector, facing up
  T cosIH = T(0), cosOH = T(0);
  T fresnel = T(0);  // F at h for the pair's light path
  bool valid = false;
};

// f(wi, wo) without the cosine (bsdf.h), the kernel shared by rendering (T = double) and
// fitting (T = ceres::Jet):
//   reflection: F D G2 / (4 |cos_i cos_o|)                                   (Walter eq. 20)
//   refraction: |wi.h| |wo.h| (1 - F) D G2 / (|cos_i cos_o| (wi.h / etaRel + wo.h)^2)
//               for importance, divided by etaRel^2 for radiance           (Walter eq. 21)
// Walter's eq. 21 is written for light arriving from i and leaving along o: its factor
// n_o^2 / (n_i i.h + n_o o.h)^2 is 1 / (wi.h / etaRel + wo.h)^2 with i = wi (importance: light
// comes from wi) and 1 / (etaRel^2 (wi.h / etaRel + wo.h)^2) with i = wo (radiance).
template <typename T, typename Distribution> T roughDielectricEval(const Distribution& distribution,
                                                                   const T& eta, const Vec3<T>& wi,
                                                                   const Vec3<T>& wo, TransportMode mode) {
  using std::abs;
  const DielectricPair<T> pair(wi, wo, eta);
  if (!pair.valid) return T(0);
  const T d = distribution.D(pair.h);
  if (pair.reflection) return pair.fresnel * d * distribution.G2(wi, wo) / abs(T(4) * wi.z * wo.z);
  const T denominator = pair.cosIH / pair.etaRel + pair.cosOH;
  const T f = abs(pair.cosIH * pair.cosOH) * (T(1) - pair.fresnel) * d *
              smithG2Transmission(distribution, wi, wo) / (abs(wi.z * wo.z) * denominator * denominator);
  return mode == TransportMode::Radiance ? f / sqr(pair.etaRel) : f;
}

// The density of sample() per solid angle of wo (the same in both transport modes), given
// the pair's DielectricPair.
template <typename Distribution> double roughDielectricPdf(const Distribution& distribution, const Vec3d& wi,
                                                           const Vec3d& wo,
                                                           const DielectricPair<double>& pair) {
  if (!pair.valid) return 0.0;
  const double normalDensity = distribution.pdfVisible(wi.z > 0 ? wi : -wi, pair.h);
  if (pair.reflection) return reflectedDensity(normalDensity * pair.fresnel, wo, pair.h);
  return normalDensity * (1.0 - pair.fresnel) * refractionJacobian(wi, wo, pair.h, pair.etaRel);
}

template <typename Distribution>
double roughDielectricPdf(const Distribution& distribution, double eta, const Vec3d& wi, const Vec3d& wo) {
  return roughDielectricPdf(distribution, wi, wo, DielectricPair<double>(wi, wo, eta));
}

// The microfacet normal sample() draws: visible from wi. Seen from below (wi.z < 0) the
// visible facets are those whose backs face wi, i.e. the normals visible from -wi.
template <typename Distribution>
Vec3d sampleRoughDielectricNormal(const Distribution& distribution, const Vec3d& wi, const Vec2d& u) {
  return distribution.sampleVisible(wi.z > 0 ? wi : -wi, u);
}

// wi scattered by the facet m into the chosen lobe (reflect, or refract when `transmission`),
// with the model's whole pdf at wo (both lobes' selection included) and the weight
// f |cos wo| / pdf. Nothing when the scattered direction leaves the lobe's hemisphere or total
// internal reflection forbids the refraction. sample() is this with the lobe chosen with
// probability F(wi.m); rough_dielectric_albedo.h integrates it over m.
template <typename Distribution>
std::optional<BsdfSample> scatterRoughDielectric(const Distribution& distribution, double eta,
                                                 const Vec3d& wi, const Vec3d& m, bool transmission,
                                                 TransportMode mode) {
  Vec3d wo;
  if (transmission) {
    const std::optional<Refraction> t = refract(wi, m, eta);
    if (!t || !(t->w.z * wi.z < 0)) return std::nullopt;
    wo = t->w;
  } else {
    wo = reflect(wi, m);
    if (!(wo.z * wi.z > 0)) return std::nullopt;
  }
  // From here on everything comes from (wi, wo) as eval() and pdf() compute it, so that the
  // sample's pdf is pdf(wi, wo) to the last bit.
  const DielectricPair<double> pair(wi, wo, eta);
  if (!pair.valid || pair.reflection == transmission) return std::nullopt;
  const double density = roughDielectricPdf(distribution, wi, wo, pair);
  if (!(density > 0)) return std::nullopt;
  // f |cos wo| / pdf with D, F (or 1 - F), the Jacobian and the visible-normal cosines
  // cancelled, so that it stays finite where D or cos_i is tiny: G2 / G1(wi) (Heitz & d'Eon
  // 2014), times 1 / etaRel^2 for radiance through a refraction.
  if (!transmission)
    return BsdfSample{wo, Rgb(distribution.G2(wi, wo) / distribution.G1(wi)), density,
                      LobeFlags::GlossyReflection, 1.0};
  double weight = smithG2Transmission(distribution, wi, wo) / distribution.G1(wi);
  if (mode == TransportMode::Radiance) weight /= sqr(pair.etaRel);
  return BsdfSample{wo, Rgb(weight), density, LobeFlags::GlossyTransmission, pair.etaRel};
}

template <typename Distribution> class RoughDielectricBsdf final : public BsdfModel {
 public:
  // eta: the index below the surface relative to above, != 1 (an index-matched interface
  // refracts nothing, whatever its roughness; the generalised half vector is then undefined).
  // With MultipleScattering::KullaConty the roughness must be isotropic and in (0, 1], the
  // range of the compensation's tables (std::invalid_argument otherwise).
  RoughDielectricBsdf(const Distribution& distribution, double eta,
                      MultipleScattering multipleScattering = MultipleScattering::None)
      : distribution_(distribution), eta_(eta) {
    if (multipleScattering == MultipleScattering::KullaConty) {
      if (!distribution.isotropic())
        throw std::invalid_argument(
            "the rough dielectric's multiple-scattering compensation needs isotropic roughness");
      compensation_ =
          RoughDielectricCompensation::shared(microfacetTypeOf<Distribution>(), distribution.alphaX(), eta);
    }
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override {
    if (!compensation_) return Rgb(roughDielectricEval<double>(distribution_, eta_, wi, wo, mode));
    return Rgb(compensatedEval(wi, wo, 1.0 - compensation_->albedoAt(wi), mode));
  }

  // Without compensation, the density of the refracted or reflected sampled normal. With it,
  // the mixture that sample() draws (the header comment).
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!compensation_) return roughDielectricPdf(distribution_, eta_, wi, wo);
    return compensatedPdf(wi, wo, compensation_->albedoAt(wi));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const override {
    if (wi.z == 0 || !std::isfinite(wi.z)) return std::nullopt;
    if (compensation_) return sampleCompensated(wi, uLobe, u, mode);
    const Vec3d m = sampleRoughDielectricNormal(distribution_, wi, u);
    const bool transmission = chooseLobe(uLobe, fresnelDielectric(glm::dot(wi, m), eta_)).lobe != 0;
    return scatterRoughDielectric(distribution_, eta_, wi, m, transmission, mode);
  }

  LobeFlags flags() const override {
    const LobeFlags single = LobeFlags::GlossyReflection | LobeFlags::GlossyTransmission;
    return compensation_ ? single | LobeFlags::DiffuseReflection | LobeFlags::DiffuseTransmission : single;
  }
  // A compensated dielectric absorbs nothing and returns what single scattering misses.
  bool isLossless() const override { return compensation_ != nullptr; }
  // The compensation returns 1 - E_s(wi) of the table, single scattering the exact E_s(wi): the
  // furnace is off by the table's error, within 1e-4 of direct quadrature
  // (rough_dielectric_multiscatter_test.cpp).
  double losslessAccuracy() const override { return compensation_ ? 1e-4 : 0.0; }
  double interiorIndex() const override { return eta_; }

  const Distribution& distribution() const { return distribution_; }
  double eta() const { return eta_; }
  MultipleScattering multipleScattering() const {
    return compensation_ ? MultipleScattering::KullaConty : MultipleScattering::None;
  }
  // The compensation lobe, or null.
  const RoughDielectricCompensation* compensation() const { return compensation_.get(); }

 private:
  // eval() and pdf() with compensation, given E_s(wi) (a table lookup, done once per sample).
  double compensatedEval(const Vec3d& wi, const Vec3d& wo, double lossI, TransportMode mode) const {
    return roughDielectricEval<double>(distribution_, eta_, wi, wo, mode) +
           compensation_->eval(wi, wo, lossI, mode);
  }
  double compensatedPdf(const Vec3d& wi, const Vec3d& wo, double albedoI) const {
    return albedoI * roughDielectricPdf(distribution_, eta_, wi, wo) +
           (1.0 - albedoI) * compensation_->pdf(wi, wo);
  }

  // Single scattering with probability E_s(wi), its lobe then chosen by Fresnel with uLobe
  // rescaled to [0, 1); the compensation lobe otherwise, with uLobe rescaled likewise. The
  // weight is the mixture's f |cos| / pdf, computed as eval() and pdf() compute them.
  std::optional<BsdfSample> sampleCompensated(const Vec3d& wi, double uLobe, const Vec2d& u,
                                              TransportMode mode) const {
    const double albedoI = compensation_->albedoAt(wi);
    const LobeChoice choice = chooseLobe(uLobe, albedoI);
    const bool single = choice.lobe == 0;
    std::optional<Vec3d> wo;
    if (single) {
      const Vec3d m = sampleRoughDielectricNormal(distribution_, wi, u);
      const bool transmission = chooseLobe(choice.u, fresnelDielectric(glm::dot(wi, m), eta_)).lobe != 0;
      if (const auto s = scatterRoughDielectric(distribution_, eta_, wi, m, transmission, mode)) wo = s->wo;
    } else {
      wo = compensation_->sample(wi, choice.u, u);
    }
    if (!wo || wo->z == 0) return std::nullopt;
    const double density = compensatedPdf(wi, *wo, albedoI);
    if (!(density > 0)) return std::nullopt;
    const bool transmitted = wo->z * wi.z < 0;
    const double weight = compensatedEval(wi, *wo, 1.0 - albedoI, mode) * std::abs(wo->z) / density;
    const LobeFlags lobe =
        single ? (transmitted ? LobeFlags::GlossyTransmission : LobeFlags::GlossyReflection)
               : (transmitted ? LobeFlags::DiffuseTransmission : LobeFlags::DiffuseReflection);
    return BsdfSample{*wo, Rgb(weight), density, lobe, transmitted ? relativeIndex(wi, *wo, eta_) : 1.0};
  }

  Distribution distribution_;
  double eta_;
  std::shared_ptr<const RoughDielectricCompensation> compensation_;  // set with compensation
};

// The rough dielectric for the registry. alphaX and alphaY must be positive and finite, eta
// positive, finite and != 1, and with compensation alphaX == alphaY <= 1 (std::invalid_argument
// otherwise; the registry reports the allowed range to the user).
std::unique_ptr<BsdfModel> makeRoughDielectric(
    MicrofacetType type, double alphaX, double alphaY, double eta,
    MultipleScattering multipleScattering = MultipleScattering::None);

struct MaterialModel;

// The material registry's "rough-dielectric" model (materials/registry/model_list.h).
MaterialModel roughDielectricModel();

}  // namespace scatterlab
