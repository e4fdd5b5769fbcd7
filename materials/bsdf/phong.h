// The normalised Phong family: a Lambertian term plus one normalised cosine-power lobe.
//  - Phong: the modified Phong model (Lafortune & Willems 1994, "Using the Modified Phong
//    Reflectance Model for Physically Based Rendering", eq. 7), lobe about the mirror direction.
//  - Blinn-Phong: the normalised half-vector lobe as Ngan et al. 2005 ("Experimental Analysis
//    of BRDF Models", appendix) list it, D(h) = (n+2)/(2 pi) cos^n theta_h.
// Both are sampled by choosing the diffuse or the glossy part (glossySelectionProbability)
// and the pdf is the exact mixture. Both are reciprocal.
#pragma once

#include "materials/bsdf/cosine_lobe.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

// Phong: f = kd/pi + ks (n+2)/(2 pi) max(0, cos alpha)^n, alpha between wo and the mirror
// direction of wi. Albedo <= kd + ks (equality at normal incidence), so kd + ks <= 1 conserves
// energy.
template <typename T>
RgbT<T> phongEval(const RgbT<T>& kd, const RgbT<T>& ks, const T& n, const Vec3d& wi, const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return RgbT<T>(T(0));
  const double cosAlpha = glm::dot(reflect(wi, Vec3d(0, 0, 1)), wo);
  return kd * T(InvPi) + ks * normalizedCosinePower(cosAlpha, n);
}

// Blinn-Phong (Ngan): f = kd/pi + ks (n+2)/(2 pi) cos^n theta_h, h = normalize(wi + wo).
// This lobe is NOT energy-normalised in wo: its albedo approaches 4 ks (n+2)/(n+1) at normal
// incidence for large n, so albedo <= 1 needs roughly kd + 4 ks <= 1 (the user's job).
template <typename T>
RgbT<T> blinnPhongEval(const RgbT<T>& kd, const RgbT<T>& ks, const T& n, const Vec3d& wi, const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return RgbT<T>(T(0));
  const Vec3d h = glm::normalize(wi + wo);
  return kd * T(InvPi) + ks * normalizedCosinePower(h.z, n);
}

// The glossy lobes' sampling strategies (exact densities).
struct PhongLobe {
  static Vec3d mirror(const Vec3d& wi) { return {-wi.x, -wi.y, wi.z}; }
  template <typename T>
  static RgbT<T> eval(const RgbT<T>& kd, const RgbT<T>& ks, const T& n, const Vec3d& wi, const Vec3d& wo) {
    return phongEval(kd, ks, n, wi, wo);
  }
  static double pdf(double n, const Vec3d& wi, const Vec3d& wo) {
    return cosinePowerPdf(glm::dot(mirror(wi), wo), n);
  }
  static std::optional<Vec3d> sample(double n, const Vec3d& wi, const Vec2d& u) {
    return sampleCosinePowerAbout(mirror(wi), u, n);
  }
};

// h from (n+1)/(2 pi) cos^n theta_h, wo = reflect(wi, h); pdf(wo) = pdf(h) / (4 wo.h).
struct BlinnPhongLobe {
  template <typename T>
  static RgbT<T> eval(const RgbT<T>& kd, const RgbT<T>& ks, const T& n, const Vec3d& wi, const Vec3d& wo) {
    return blinnPhongEval(kd, ks, n, wi, wo);
  }
  static double pdf(double n, const Vec3d& wi, const Vec3d& wo) {
    const Vec3d h = glm::normalize(wi + wo);
    const double woDotH = glm::dot(wo, h);
    if (!(woDotH > 0)) return 0.0;
    return cosinePowerPdf(h.z, n) / (4.0 * woDotH);
  }
  static std::optional<Vec3d> sample(double n, const Vec3d& wi, const Vec2d& u) {
    const Vec3d h = sampleCosinePower(u, n);
    if (!(glm::dot(wi, h) > 0)) return std::nullopt;
    return reflect(wi, h);
  }
};

// kd/pi + a glossy Lobe scaled by ks; exponent n >= 0.
template <typename Lobe> class NormalizedPhongBsdf final : public BsdfModel {
 public:
  NormalizedPhongBsdf(const Rgb& kd, const Rgb& ks, double exponent)
      : kd_(kd), ks_(ks), n_(exponent), glossyProbability_(glossySelectionProbability(kd, ks)) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return Lobe::eval(kd_, ks_, n_, wi, wo);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return (1.0 - glossyProbability_) * cosineHemispherePdf(wo.z) +
           glossyProbability_ * Lobe::pdf(n_, wi, wo);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    if (chooseLobe(uLobe, glossyProbability_).lobe != 0)
      return finishSample(*this, wi, sampleCosineHemisphere(u), LobeFlags::DiffuseReflection);
    const std::optional<Vec3d> wo = Lobe::sample(n_, wi, u);
    if (!wo) return std::nullopt;
    return finishSample(*this, wi, *wo, LobeFlags::GlossyReflection);
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection | LobeFlags::GlossyReflection; }

  const Rgb& kd() const { return kd_; }
  const Rgb& ks() const { return ks_; }
  double exponent() const { return n_; }

 private:
  Rgb kd_, ks_;
  double n_;
  double glossyProbability_;
};

using PhongBsdf = NormalizedPhongBsdf<PhongLobe>;
using BlinnPhongBsdf = NormalizedPhongBsdf<BlinnPhongLobe>;

struct MaterialModel;

// The material registry's "phong" model (materials/registry/model_list.h).
MaterialModel phongModel();
// The material registry's "blinn-phong" model (materials/registry/model_list.h).
MaterialModel blinnPhongModel();

}  // namespace scatterlab
