// Lambertian reflection: f = albedo / pi, sampled cosine-weighted (Malley's method), so
// the weight is exactly the albedo.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/core/warp.h"

namespace scatterlab {

// The kernel shared by rendering and fitting (T = double or ceres::Jet).
template <typename T> RgbT<T> lambertianEval(const RgbT<T>& albedo) { return albedo * T(InvPi); }

class LambertianBsdf final : public BsdfModel {
 public:
  explicit LambertianBsdf(const Rgb& albedo) : albedo_(albedo) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0 || wo.z <= 0) return Rgb(0.0);
    return lambertianEval(albedo_);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0 || wo.z <= 0) return 0.0;
    return cosineHemispherePdf(wo.z);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0) return std::nullopt;
    const Vec3d wo = sampleCosineHemisphere(u);
    if (wo.z <= 0) return std::nullopt;  // u on the disk's rim: measure zero, but no 0/0
    return BsdfSample{wo, albedo_, cosineHemispherePdf(wo.z), LobeFlags::DiffuseReflection, 1.0};
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection; }
  bool isLossless() const override { return albedo_ == Rgb(1.0); }

  const Rgb& albedo() const { return albedo_; }

 private:
  Rgb albedo_;
};

struct MaterialModel;

// The material registry's "lambertian" model (materials/registry/model_list.h).
MaterialModel lambertianModel();

}  // namespace scatterlab
