// Cook-Torrance as Ngan et al. 2005 ("Experimental Analysis of BRDF Models", EGSR 2005,
// sec. 3) fitted it, i.e. bsdfbenchmark's NganCookTorrance (include/bsdfmodel/ngan.h):
//   f = albedo D(h) G(wi, wo) F(wi.h) / (pi cos_i cos_o)
// with the normalised isotropic Beckmann D (Walter et al. 2007 eq. 25), the V-groove
// shadowing of Cook & Torrance 1982 (eq. in sec. "Geometrical attenuation factor")
// G = min(1, 2 h.z cos_o / (wo.h), 2 h.z cos_i / (wi.h)), Schlick's Fresnel with F0 = the
// parameter Ngan calls `eta`, and Cook's normalisation (pi instead of Walter's 4).
// Reciprocal (every factor is symmetric in wi, wo). Not energy bounded for albedo = 1: the
// pi normalisation reflects up to 4/pi of the albedo (a near-mirror lobe at normal incidence
// reflects 4/pi F0 albedo), so albedo <= 1 is guaranteed for albedo <= pi/4.
// Sampling: h with density D(h) h.z (Beckmann classic), wo = reflect(wi, h), pdf
// D(h) h.z / (4 wo.h).
#pragma once

#include <stdexcept>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/half_vector.h"
#include "materials/bsdf/microfacet.h"

namespace scatterlab {

// V-groove shadowing-masking (Cook & Torrance 1982); wi.h = wo.h for a reflection pair.
template <typename T> T vGrooveShadowing(const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& h) {
  const T cosIH = glm::dot(wi, h), cosOH = glm::dot(wo, h);
  T g = T(1);
  const T gi = T(2) * h.z * wi.z / cosIH;
  const T go = T(2) * h.z * wo.z / cosOH;
  if (gi < g) g = gi;
  if (go < g) g = go;
  return g;
}

// The kernel shared by rendering and fitting (T = double or ceres::Jet).
template <typename T> RgbT<T> nganCookTorranceEval(const RgbT<T>& albedo, const T& f0, const T& roughness,
                                                   const Vec3<T>& wi, const Vec3<T>& wo) {
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return RgbT<T>(T(0));
  const Vec3<T> h = reflectionHalfVector(wi, wo);
  const T d = BeckmannDistribution<T>(roughness, roughness).D(h);
  const T g = vGrooveShadowing(wi, wo, h);
  // Ngan's code evaluates F at the mean of wi.h and wo.h (equal up to round-off; the mean
  // keeps f(wi, wo) and f(wo, wi) bit-identical).
  const T f = fresnelSchlick(f0, T(0.5) * (glm::dot(wi, h) + glm::dot(wo, h)));
  return albedo * (d * g * f / (T(Pi) * wi.z * wo.z));
}

class NganCookTorranceBsdf final : public BsdfModel {
 public:
  NganCookTorranceBsdf(const Rgb& albedo, double f0, double roughness)
      : albedo_(albedo), f0_(f0), distribution_(roughness, roughness) {
    if (!(roughness > 0) || !std::isfinite(roughness))
      throw std::invalid_argument("Cook-Torrance: roughness must be positive and finite");
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return nganCookTorranceEval<double>(albedo_, f0_, distribution_.alphaX(), wi, wo);
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return classicReflectionPdf(distribution_, wi, wo);
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    const std::optional<ReflectionSample> s = sampleClassicReflection(distribution_, wi, u);
    if (!s) return std::nullopt;
    const Vec3d &wo = s->wo, &h = s->h;
    // f cos_o / pdf with D and cos_o cancelled: albedo G F 4 (wo.h) / (pi cos_i h.z).
    const double cosIH = glm::dot(wi, h), cosOH = glm::dot(wo, h);
    const double fresnel = fresnelSchlick(f0_, 0.5 * (cosIH + cosOH));
    const double factor = vGrooveShadowing(wi, wo, h) * fresnel * 4.0 * cosOH / (Pi * wi.z * h.z);
    return BsdfSample{wo, albedo_ * factor, s->pdf, LobeFlags::GlossyReflection, 1.0};
  }

  LobeFlags flags() const override { return LobeFlags::GlossyReflection; }

  const Rgb& albedo() const { return albedo_; }
  double f0() const { return f0_; }
  double roughness() const { return distribution_.alphaX(); }

 private:
  Rgb albedo_;
  double f0_;
  BeckmannDistribution<double> distribution_;
};

struct MaterialModel;

// The material registry's "ngan-cook-torrance" model (materials/registry/model_list.h).
MaterialModel nganCookTorranceModel();

}  // namespace scatterlab
