// Ashikhmin & Shirley 2000, "An Anisotropic Phong BRDF Model" (JGT 5(2)): specular lobe
// (eq. 4), diffuse term (eq. 5) and the half-vector sampler (eq. 9-10, density eq. 8), plus
// Ngan et al. 2005's isotropic variant (bsdfbenchmark NganAshikhminShirley, ngan.h): the
// specular lobe only, nu = nv = sharpness, Schlick F0 = fresnelReflectance, scaled by an RGB
// specular albedo (Ngan adds a separate Lambertian).
//   specular f_s = sqrt((nu+1)(nv+1)) / (8 pi) (n.h)^(nu cos^2 phi_h + nv sin^2 phi_h)
//                  / ((h.k) max(cos_i, cos_o)) F(h.k),   F = Rs + (1 - Rs)(1 - h.k)^5
//   diffuse  f_d = 28 Rd / (23 pi) (1 - Rs) (1 - (1 - cos_i/2)^5) (1 - (1 - cos_o/2)^5)
// Reciprocal (every factor is symmetric in wi, wo). Sampling: a lobe by uLobe, then h from
// p(h) = sqrt((nu+1)(nv+1)) / (2 pi) (n.h)^(nu cos^2 + nv sin^2) and wo = reflect(wi, h),
// pdf p(h) / (4 wo.h); or the diffuse lobe cosine-weighted. The pdf is the exact mixture.
#pragma once

#include <stdexcept>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/half_vector.h"
#include "materials/core/lobe_choice.h"
#include "materials/core/warp.h"

namespace scatterlab {

// (n.h)^(nu cos^2 phi_h + nv sin^2 phi_h), the anisotropic Phong lobe of the half vector,
// written with hx^2 + hy^2 instead of 1 - hz^2 (no cancellation near the pole, where
// the exponent's phi is undefined and the value is 1 for any exponent).
template <typename T> T ashikhminShirleyLobe(const T& nu, const T& nv, const Vec3<T>& h) {
  using std::pow;
  const T hx2 = h.x * h.x, hy2 = h.y * h.y;
  const T s2 = hx2 + hy2;
  if (!(s2 > T(0))) return T(1);
  const T exponent = (nu * hx2 + nv * hy2) / s2;
  return pow(h.z, exponent);
}

// Specular lobe (eq. 4) times an RGB scale (1 in the paper, Ngan's albedo). T = double or Jet.
template <typename T> RgbT<T> ashikhminShirleySpecularEval(const RgbT<T>& scale, const RgbT<T>& rs,
                                                           const T& nu, const T& nv, const Vec3<T>& wi,
                                                           const Vec3<T>& wo) {
  using std::sqrt;
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return RgbT<T>(T(0));
  const Vec3<T> h = reflectionHalfVector(wi, wo);
  const T cosIH = glm::dot(wi, h);
  const T maxCos = wi.z > wo.z ? wi.z : wo.z;
  const T lobe =
      sqrt((nu + T(1)) * (nv + T(1))) / T(8.0 * Pi) * ashikhminShirleyLobe(nu, nv, h) / (cosIH * maxCos);
  return scale * fresnelSchlick(rs, cosIH) * lobe;
}

// Diffuse term (eq. 5).
template <typename T> RgbT<T> ashikhminShirleyDiffuseEval(const RgbT<T>& rd, const RgbT<T>& rs,
                                                          const Vec3<T>& wi, const Vec3<T>& wo) {
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return RgbT<T>(T(0));
  const auto fifth = [](const T& x) {
    const T x2 = x * x;
    return x2 * x2 * x;
  };
  const T angular = (T(1) - fifth(T(1) - T(0.5) * wi.z)) * (T(1) - fifth(T(1) - T(0.5) * wo.z));
  return rd * (RgbT<T>(T(1)) - rs) * (T(28.0 / (23.0 * Pi)) * angular);
}

class AshikhminShirleyBsdf final : public BsdfModel {
 public:
  // The paper's model: specular (scale 1) plus diffuse.
  static AshikhminShirleyBsdf paper(double nu, double nv, const Rgb& rs, const Rgb& rd) {
    return AshikhminShirleyBsdf(nu, nv, rs, Rgb(1.0), rd, true);
  }
  // Ngan et al. 2005: isotropic specular lobe only, scaled by the specular albedo.
  static AshikhminShirleyBsdf ngan(const Rgb& albedo, double fresnelReflectance, double sharpness) {
    return AshikhminShirleyBsdf(sharpness, sharpness, Rgb(fresnelReflectance), albedo, Rgb(0.0), false);
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    Rgb f = ashikhminShirleySpecularEval<double>(scale_, rs_, nu_, nv_, wi, wo);
    if (diffuse_) f += ashikhminShirleyDiffuseEval<double>(rd_, rs_, wi, wo);
    return f;
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    const Vec3d h = reflectionHalfVector(wi, wo);
    const double specular = reflectedDensity(halfVectorPdf(h), wo, h);
    return diffuse_
               ? specularProbability_ * specular + (1.0 - specularProbability_) * cosineHemispherePdf(wo.z)
               : specular;
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    const bool specular = !diffuse_ || chooseLobe(uLobe, specularProbability_).lobe == 0;
    const Vec3d wo = specular ? reflect(wi, sampleHalfVector(u)) : sampleCosineHemisphere(u);
    if (!(wo.z > 0)) return std::nullopt;
    const double density = pdf(wi, wo);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wo, eval(wi, wo) * (wo.z / density), density,
                      specular ? LobeFlags::GlossyReflection : LobeFlags::DiffuseReflection, 1.0};
  }

  LobeFlags flags() const override {
    return diffuse_ ? LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection
                    : LobeFlags::GlossyReflection;
  }

  // p(h) = sqrt((nu+1)(nv+1)) / (2 pi) (n.h)^(nu cos^2 phi + nv sin^2 phi) (eq. 8).
  double halfVectorPdf(const Vec3d& h) const {
    if (!(h.z > 0)) return 0.0;
    return normalization_ * Inv2Pi * ashikhminShirleyLobe(nu_, nv_, h);
  }

  // Eq. 9-10: phi = atan(sqrt((nu+1)/(nv+1)) tan(pi u / 2)) in the first quadrant, mirrored
  // into the quadrant u.x selects; cos theta = (1 - u.y)^(1 / (nu cos^2 phi + nv sin^2 phi + 1)).
  Vec3d sampleHalfVector(const Vec2d& u) const {
    const double scaled = 4.0 * u.x;
    const int quadrant = std::min(int(scaled), 3);
    const double t = scaled - quadrant;
    const double phi0 = std::atan(anisotropyRatio_ * std::tan(PiOver2 * t));
    double cosPhi = std::cos(phi0), sinPhi = std::sin(phi0);
    if (quadrant == 1 || quadrant == 2) cosPhi = -cosPhi;
    if (quadrant == 2 || quadrant == 3) sinPhi = -sinPhi;
    const double exponent = nu_ * cosPhi * cosPhi + nv_ * sinPhi * sinPhi;
    // cos = exp(log(1 - u) / (e + 1)); sin^2 = 1 - cos^2 = -expm1(2 log(1 - u) / (e + 1)),
    // precise for the sharp lobes (e ~ 1e5) where cos rounds to 1.
    const double logCos = std::log1p(-u.y) / (exponent + 1.0);
    const double cosTheta = std::exp(logCos);
    const double sinTheta = safeSqrt(-std::expm1(2.0 * logCos));
    return {sinTheta * cosPhi, sinTheta * sinPhi, cosTheta};
  }

  double nu() const { return nu_; }
  double nv() const { return nv_; }
  const Rgb& rs() const { return rs_; }
  const Rgb& rd() const { return rd_; }
  const Rgb& scale() const { return scale_; }
  bool hasDiffuse() const { return diffuse_; }
  double specularProbability() const { return specularProbability_; }

 private:
  AshikhminShirleyBsdf(double nu, double nv, const Rgb& rs, const Rgb& scale, const Rgb& rd, bool diffuse)
      : nu_(nu),
        nv_(nv),
        rs_(rs),
        scale_(scale),
        rd_(rd),
        diffuse_(diffuse),
        normalization_(std::sqrt((nu + 1.0) * (nv + 1.0))),
        anisotropyRatio_(std::sqrt((nu + 1.0) / (nv + 1.0))) {
    if (!(nu >= 0) || !(nv >= 0) || !std::isfinite(nu) || !std::isfinite(nv))
      throw std::invalid_argument("Ashikhmin-Shirley: exponents must be finite and >= 0");
    // Lobe choice in proportion to the lobes' normal-incidence weights (specular ~ Rs, diffuse
    // ~ Rd (1 - Rs)), kept in [0.1, 0.9] so that neither lobe is left unsampled.
    const double specularWeight = (scale.x * rs.x + scale.y * rs.y + scale.z * rs.z) / 3.0;
    const double diffuseWeight = (rd.x * (1.0 - rs.x) + rd.y * (1.0 - rs.y) + rd.z * (1.0 - rs.z)) / 3.0;
    const double total = specularWeight + diffuseWeight;
    specularProbability_ = std::clamp(total > 0 ? specularWeight / total : 0.5, 0.1, 0.9);
  }

  double nu_, nv_;
  Rgb rs_, scale_, rd_;
  bool diffuse_;
  double normalization_, anisotropyRatio_;
  double specularProbability_ = 1.0;
};

struct MaterialModel;

// The material registry's "ashikhmin-shirley" model (materials/registry/model_list.h).
MaterialModel ashikhminShirleyModel();
// The material registry's "ngan-ashikhmin-shirley" model (materials/registry/model_list.h).
MaterialModel nganAshikhminShirleyModel();

}  // namespace scatterlab
