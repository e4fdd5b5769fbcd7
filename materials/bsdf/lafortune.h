// Lafortune generalised cosine lobes (Lafortune et al. 1997, "Non-Linear Approximation of
// Reflectance Functions", eq. 4): f = kd/pi + sum_i rho_i max(0, Cx wi.x wo.x + Cy wi.y wo.y +
// Cz wi.z wo.z)^n_i, optionally with Ngan et al. 2005's normalisation of each lobe,
// (n+2) / (2 pi max(Cz^2, Cxy^2)^(n/2)) (bsdfbenchmark include/bsdfmodel/ngan.h).
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "materials/bsdf/cosine_lobe.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

enum class LafortuneNormalization { None, Ngan };

template <typename T> struct LafortuneLobeT {
  RgbT<T> rho{T(0)};
  Vec3<T> c{T(-1), T(-1), T(1)};  // (Cx, Cy, Cz); (-1, -1, 1) is the mirror direction
  T n{T(1)};
};
using LafortuneLobe = LafortuneLobeT<double>;

// max(|Cx|, |Cy|, |Cz|) = sqrt(max(Cz^2, Cxy^2)), where Ngan's factor puts the lobe's peak
// (Ngan's lobes are isotropic, Cx = Cy; an anisotropic lobe uses the larger of the two).
template <typename T> T lafortunePeak(const Vec3<T>& c) {
  using std::abs;
  T m = abs(c.z);
  if (abs(c.x) > m) m = abs(c.x);
  if (abs(c.y) > m) m = abs(c.y);
  return m;
}

// One lobe's value rho max(0, d)^n, d = C . (wi * wo). With Ngan's normalisation it is
// rho (n+2) / (2 pi max(Cz^2, Cxy^2)^(n/2)) max(0, d)^n, evaluated as rho (n+2)/(2 pi)
// max(0, d / peak)^n so that neither factor under- or overflows at large n. A lobe with C = 0
// contributes 0.
template <typename T> RgbT<T> lafortuneLobeEval(const LafortuneLobeT<T>& lobe,
                                                LafortuneNormalization normalization, const Vec3d& wi,
                                                const Vec3d& wo) {
  const T d = lobe.c.x * T(wi.x * wo.x) + lobe.c.y * T(wi.y * wo.y) + lobe.c.z * T(wi.z * wo.z);
  if (normalization == LafortuneNormalization::None) return lobe.rho * clampedCosinePower(d, lobe.n);
  const T peak = lafortunePeak(lobe.c);
  if (!(peak > T(0))) return RgbT<T>(T(0));
  return lobe.rho * normalizedCosinePower(d / peak, lobe.n);
}

template <typename T> RgbT<T> lafortuneEval(const RgbT<T>& kd, const std::vector<LafortuneLobeT<T>>& lobes,
                                            LafortuneNormalization normalization, const Vec3d& wi,
                                            const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return RgbT<T>(T(0));
  RgbT<T> f = kd * T(InvPi);
  for (const auto& lobe : lobes) f += lafortuneLobeEval(lobe, normalization, wi, wo);
  return f;
}

// Sampling: the diffuse part with weight mean(kd), lobe i with weight mean(rho_i) (|C_i wi| /
// max|C_i|)^n_i (the fraction of the normalised lobe's peak reachable from wi); a chosen lobe
// samples (n+1)/(2 pi) cos^n about its axis normalize(C * wi). pdf = the weighted mixture.
class LafortuneBsdf final : public BsdfModel {
 public:
  // Lobe weights live in a fixed array so that pdf() and sample() never allocate.
  static constexpr size_t MaxLobes = 8;

  LafortuneBsdf(const Rgb& kd, std::vector<LafortuneLobe> lobes, LafortuneNormalization normalization)
      : kd_(kd), lobes_(std::move(lobes)), normalization_(normalization) {
    if (lobes_.size() > MaxLobes)
      throw std::invalid_argument("a Lafortune BRDF has at most " + std::to_string(MaxLobes) +
                                  " lobes, got " + std::to_string(lobes_.size()));
  }

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return lafortuneEval(kd_, lobes_, normalization_, wi, wo);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    const Weights w = weights(wi);
    if (!(w.total > 0)) return 0.0;
    double p = w.diffuse * cosineHemispherePdf(wo.z);
    for (size_t i = 0; i < lobes_.size(); ++i)
      if (w.lobe[i] > 0) p += w.lobe[i] * cosinePowerPdf(glm::dot(axis(i, wi), wo), lobes_[i].n);
    return p / w.total;
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    const Weights w = weights(wi);
    if (!(w.total > 0)) return std::nullopt;
    // Probability 0: the diffuse part, i + 1: lobe i (the weights over their total).
    std::array<double, MaxLobes + 1> probabilities{};
    probabilities[0] = w.diffuse / w.total;
    for (size_t i = 0; i < lobes_.size(); ++i) probabilities[i + 1] = w.lobe[i] / w.total;
    const int chosen = chooseLobe(uLobe, std::span(probabilities.data(), lobes_.size() + 1)).lobe;
    if (chosen < 0) return std::nullopt;
    if (chosen == 0) return finishSample(*this, wi, sampleCosineHemisphere(u), LobeFlags::DiffuseReflection);
    const size_t lobe = size_t(chosen - 1);
    const Vec3d wo = sampleCosinePowerAbout(axis(lobe, wi), u, lobes_[lobe].n);
    return finishSample(*this, wi, wo, LobeFlags::GlossyReflection);
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection | LobeFlags::GlossyReflection; }

  const Rgb& kd() const { return kd_; }
  const std::vector<LafortuneLobe>& lobes() const { return lobes_; }

 private:
  struct Weights {
    double diffuse = 0, total = 0;
    std::array<double, MaxLobes> lobe{};
  };
  Vec3d axis(size_t i, const Vec3d& wi) const { return glm::normalize(lobes_[i].c * wi); }
  Weights weights(const Vec3d& wi) const {
    Weights w;
    w.diffuse = channelMean(kd_);
    w.total = w.diffuse;
    for (size_t i = 0; i < lobes_.size(); ++i) {
      const LafortuneLobe& l = lobes_[i];
      const double reach = glm::length(l.c * wi);
      const double peak = lafortunePeak(l.c);
      if (!(reach > 0)) continue;
      w.lobe[i] = channelMean(l.rho) * std::pow(reach / peak, l.n);
      w.total += w.lobe[i];
    }
    return w;
  }

  Rgb kd_;
  std::vector<LafortuneLobe> lobes_;
  LafortuneNormalization normalization_;
};

struct MaterialModel;

// The material registry's "lafortune" model (materials/registry/model_list.h).
MaterialModel lafortuneModel();

}  // namespace scatterlab
