// Rough plastic: a clear dielectric coating of index eta with a rough (GGX or Beckmann,
// isotropic) interface over a Lambertian base of reflectance kd, with the light that is
// reflected back and forth between the base and the underside of the coating summed up.
//
//   f = f_s + f_d
//   f_s(wi, wo) = D(h) F(wi.h, eta) G2(wi, wo) / (4 cos_i cos_o)
//                 (Walter et al. 2007 eq. 20, exact dielectric F; Smith height-correlated G2,
//                 Heitz 2014 eq. 99)
//   f_d(wi, wo) = kd (1 - E(wi)) (1 - E(wo)) / (pi eta^2 (1 - kd Fdr_int)),
//                 Fdr_int = 1 - (1 - Ebar) / eta^2
// where E(w) is the directional albedo of f_s and Ebar = (1/pi) integral E cos dw its cosine
// average (microfacet_albedo.h).
//
// Derivation (the layered structure of Weidlich & Wilkie 2007, "Arbitrarily Layered
// Micro-Facet Surfaces", which Mitsuba 0.6's plastic/roughplastic implement with
// f_d = kd T12(wi) T21(wo) / (pi eta^2 (1 - kd Fdr)); the 1 - E coupling of Kelemen &
// Szirmay-Kalos 2001, "A Microfacet Based Coupled Specular-Matte BRDF Model with Importance
// Sampling"):
//  1. Of the light arriving from wi, the coating reflects E(wi); the rest, 1 - E(wi), enters
//     (nothing is absorbed in the clear coating; energy the single-scattering microfacet model
//     does not reflect is counted as transmitted).
//  2. The base reflects kd of it diffusely, so the radiance under the coating is isotropic.
//  3. An isotropic field escapes through the interface with probability T_int = 1 - Fdr_int
//     and returns to the base with Fdr_int, where kd of it is reflected again:
//     sum_k (kd Fdr_int)^k = 1 / (1 - kd Fdr_int).
//  4. The escaping radiance is distributed over wo like the transmittance 1 - E(wo)
//     (reciprocity of the interface) and divided by eta^2 on leaving the denser medium (the
//     n^2 law of radiance, Veach 1997 section 5.2).
//  5. The exit distribution must carry exactly the escape probability:
//     (1 / (pi eta^2)) integral (1 - E(wo)) cos dwo = (1 - Ebar) / eta^2 = T_int. This fixes
//     Fdr_int. For a smooth coating E = F and Ebar = Fdr(eta), and the identity
//     1 - Fdr(eta) = eta^2 (1 - Fdr(1/eta)) (diffuse_fresnel.h) makes Fdr_int = Fdr(1/eta),
//     the internal diffuse Fresnel reflectance: f_d is then exactly Mitsuba's smooth plastic
//     term (1 - F(wi)) (1 - F(wo)) kd / (pi eta^2 (1 - kd Fdr(1/eta))).
// Why 1 - E and not the smooth 1 - F for a rough coating: E(wi) exceeds F(wi) for small alpha
// (the visible normals see the Fresnel curve at larger angles), by up to ~5e-4 for eta
// 1.1..1.5 and alpha 0.05..0.1, so a white base would reflect E + (1 - F) > 1 (the kit's
// albedo check allows 1e-4). And Fdr_int must then be the rough one of step 5: with
// T = 1 - E, the smooth Fdr(1/eta) would break the balance of step 5 by (Fdr(eta) - Ebar) /
// (1 - Fdr(eta)) of the escaping light, 17% for GGX alpha 1 and eta 2.4.
//
// Energy: the directional albedo is E(wi) + (1 - E(wi)) A_d with
// A_d = kd (1 - Ebar) / (eta^2 (1 - kd) + kd (1 - Ebar)), increasing in kd and 1 at kd = 1.
// So the albedo never exceeds 1, and a white base (kd = 1) is lossless: the coating's
// single-scattering loss comes back through the diffuse path, as it does for a clear layer.
// (Up to the tabulation of E: within 3e-5.) Both terms are symmetric in wi, wo: reciprocal.
//
// Sampling: the specular lobe by its visible normals (Heitz 2018; Heitz & d'Eon 2014) with
// probability P(wi) = E(wi) / (E(wi) + (1 - E(wi)) mean(A_d)), the ratio of the two lobes'
// albedos at wi, else cosine-weighted; pdf() is that mixture exactly.
//
// Roughness is isotropic (as in Mitsuba's roughplastic): E of an anisotropic coating depends on
// the azimuth too, at grazing incidence on the scale alpha_x / alpha_y. The kernels are
// templated on T for fitting; E and Ebar are tables in double (no derivative in alpha).
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/half_vector.h"
#include "materials/bsdf/microfacet.h"
#include "materials/bsdf/microfacet_albedo.h"
#include "materials/bsdf/microfacet_type.h"
#include "materials/core/lobe_choice.h"
#include "materials/core/warp.h"

namespace scatterlab {

// f_s: single-scattering microfacet reflection off a dielectric of relative index eta, one-sided.
template <typename T, typename Distribution>
T microfacetDielectricReflectionEval(const Distribution& distribution, const T& eta, const Vec3<T>& wi,
                                     const Vec3<T>& wo) {
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return T(0);
  const Vec3<T> h = reflectionHalfVector(wi, wo);
  return distribution.D(h) * fresnelDielectric(T(glm::dot(wi, h)), eta) * distribution.G2(wi, wo) /
         (T(4) * wi.z * wo.z);
}

// f_d given the coating's albedos E(wi), E(wo) and Ebar (header comment), per channel.
template <typename T> RgbT<T> roughPlasticDiffuseEval(const RgbT<T>& kd, const T& eta, const T& albedoIn,
                                                      const T& albedoOut, const T& albedoAverage) {
  const RgbT<T> one(T(1));
  const RgbT<T> denominator = (eta * eta) * (one - kd) + kd * (T(1) - albedoAverage);
  return kd * ((T(1) - albedoIn) * (T(1) - albedoOut) * T(InvPi)) / denominator;
}

template <typename Distribution> class RoughPlasticBsdf final : public BsdfModel {
 public:
  // distribution: isotropic; kd in [0, 1]; eta >= 1 (std::invalid_argument otherwise, from
  // the albedo table).
  RoughPlasticBsdf(const Distribution& distribution, const Rgb& kd, double eta)
      : distribution_(distribution),
        kd_(kd),
        eta_(eta),
        albedo_(sharedDielectricReflectionAlbedo(distribution, eta)) {
    const double average = albedo_->hemisphericalAverage();
    const Rgb escape = kd * (1.0 - average) / ((eta * eta) * (Rgb(1.0) - kd) + kd * (1.0 - average));
    meanDiffuseAlbedo_ = (escape.x + escape.y + escape.z) / 3.0;
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return Rgb(0.0);
    return evalGiven(incidentAlbedo(wi), wi, wo);
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return pdfGiven(specularProbability(incidentAlbedo(wi)), wi, wo);
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    const double albedoIn = incidentAlbedo(wi);
    const double specular = specularProbability(albedoIn);
    const bool chooseSpecular = chooseLobe(uLobe, specular).lobe == 0;
    const Vec3d wo =
        chooseSpecular ? reflect(wi, distribution_.sampleVisible(wi, u)) : sampleCosineHemisphere(u);
    if (!(wo.z > 0)) return std::nullopt;
    // The mixture's density and value, exactly as pdf() and eval() compute them.
    const double density = pdfGiven(specular, wi, wo);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wo, evalGiven(albedoIn, wi, wo) * (wo.z / density), density,
                      chooseSpecular ? LobeFlags::GlossyReflection : LobeFlags::DiffuseReflection, 1.0};
  }

  LobeFlags flags() const override { return LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection; }
  bool isLossless() const override { return kd_ == Rgb(1.0); }
  // The coating's exact E(wi) plus the diffuse path's tabulated 1 - E(wi) (header comment,
  // "Energy"): off by the table's error of E, 3e-5.
  double losslessAccuracy() const override { return 3e-5; }

  const Distribution& distribution() const { return distribution_; }
  const Rgb& diffuse() const { return kd_; }
  double eta() const { return eta_; }
  // E(w) and Ebar of the coating, as eval() uses them.
  double coatingAlbedo(const Vec3d& w) const { return (*albedo_)(w); }
  double coatingAlbedoAverage() const { return albedo_->hemisphericalAverage(); }
  // Fdr_int = 1 - (1 - Ebar) / eta^2: what the underside of the coating reflects of an
  // isotropic field (header comment, step 5).
  double internalDiffuseReflectance() const { return 1.0 - (1.0 - coatingAlbedoAverage()) / (eta_ * eta_); }
  // P(wi): the probability of sampling the specular lobe.
  double specularSamplingProbability(const Vec3d& wi) const { return specularProbability((*albedo_)(wi)); }

 private:
  // E(wi), remembered per thread for the last incident direction: callers evaluate many wo for
  // one wi (a renderer's light samples, the kit's quadrature), and the lookup is half the cost
  // of pdf(). The same wi always gives the same value, so the memo changes no result.
  double incidentAlbedo(const Vec3d& wi) const {
    struct Memo {
      const DielectricReflectionAlbedoTable* table = nullptr;
      Vec3d wi{0.0};
      double albedo = 0.0;
    };
    thread_local Memo memo;
    if (memo.table != albedo_.get() || memo.wi != wi) memo = {albedo_.get(), wi, (*albedo_)(wi)};
    return memo.albedo;
  }

  double specularProbability(double albedoIn) const {
    const double total = albedoIn + (1.0 - albedoIn) * meanDiffuseAlbedo_;
    return total > 0 ? albedoIn / total : 0.5;  // a black, index-matched coating reflects nothing
  }

  Rgb evalGiven(double albedoIn, const Vec3d& wi, const Vec3d& wo) const {
    const double specular = microfacetDielectricReflectionEval<double>(distribution_, eta_, wi, wo);
    return Rgb(specular) + roughPlasticDiffuseEval<double>(kd_, eta_, albedoIn, (*albedo_)(wo),
                                                           albedo_->hemisphericalAverage());
  }

  double pdfGiven(double specular, const Vec3d& wi, const Vec3d& wo) const {
    const Vec3d h = reflectionHalfVector(wi, wo);
    return specular * reflectedDensity(distribution_.pdfVisible(wi, h), wo, h) +
           (1.0 - specular) * cosineHemispherePdf(wo.z);
  }

  Distribution distribution_;
  Rgb kd_;
  double eta_;
  std::shared_ptr<const DielectricReflectionAlbedoTable> albedo_;
  double meanDiffuseAlbedo_ = 0.0;  // mean over channels of A_d (header comment)
};

// The rough plastic for the registry: alpha positive and finite, kd in [0, 1], eta in [1, inf)
// (std::invalid_argument otherwise; the registry reports the allowed ranges to the user).
std::unique_ptr<BsdfModel> makeRoughPlastic(MicrofacetType type, double alpha, const Rgb& kd, double eta);

struct MaterialModel;

// The material registry's "rough-plastic" model (materials/registry/model_list.h).
MaterialModel roughPlasticModel();

}  // namespace scatterlab
