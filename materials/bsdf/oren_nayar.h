// Oren-Nayar rough diffuse reflection, the qualitative model (Oren & Nayar 1994,
// "Generalization of Lambert's Reflectance Model", eq. 30 without the interreflection term;
// as pbrt-v3's OrenNayar). Sampled cosine-weighted, with the exact cosine pdf.
#pragma once

#include "materials/bsdf/cosine_lobe.h"

namespace scatterlab {

// f = R/pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)), alpha = max(theta_i,
// theta_o), beta = min, A = 1 - sigma^2 / (2 (sigma^2 + 0.33)), B = 0.45 sigma^2 / (sigma^2 +
// 0.09); sigma is the standard deviation of the facet slope angle in RADIANS. The angular
// factor is written without angles: max(0, cos dphi) sin(alpha) tan(beta) = max(0, wi.x wo.x +
// wi.y wo.y) / max(cos theta_i, cos theta_o), finite everywhere above the horizon. Geometry
// stays double; only R and sigma are T.
template <typename T>
RgbT<T> orenNayarEval(const RgbT<T>& albedo, const T& sigma, const Vec3d& wi, const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return RgbT<T>(T(0));
  const T s2 = sigma * sigma;
  const T a = T(1) - s2 / (T(2) * (s2 + T(0.33)));
  const T b = T(0.45) * s2 / (s2 + T(0.09));
  const double angular = std::max(0.0, wi.x * wo.x + wi.y * wo.y) / std::max(wi.z, wo.z);
  return albedo * (T(InvPi) * (a + b * T(angular)));
}

class OrenNayarBsdf final : public BsdfModel {
 public:
  // sigma in radians, [0, pi/2].
  OrenNayarBsdf(const Rgb& albedo, double sigma) : albedo_(albedo), sigma_(sigma) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return orenNayarEval(albedo_, sigma_, wi, wo);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return cosineHemispherePdf(wo.z);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    return finishSample(*this, wi, sampleCosineHemisphere(u), LobeFlags::DiffuseReflection);
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection; }

  const Rgb& albedo() const { return albedo_; }
  double sigma() const { return sigma_; }

 private:
  Rgb albedo_;
  double sigma_;
};

struct MaterialModel;

// The material registry's "oren-nayar" model (materials/registry/model_list.h).
MaterialModel orenNayarModel();

}  // namespace scatterlab
