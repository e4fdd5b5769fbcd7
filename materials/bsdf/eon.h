// EON, the energy-preserving Oren-Nayar rough diffuse BRDF (Portsmouth, Kutz & Hill 2025,
// "EON: A Practical Energy-Preserving Rough Diffuse BRDF", JCGT 14(1); the OpenPBR Surface
// specification's diffuse model). Roughness r in [0, 1], single-scattering albedo rho.
//
//  - Single scattering: Fujii's Oren-Nayar (FON, "A tiny improvement of Oren-Nayar reflectance
//    model", 2013), f_ss = (rho / pi) A (1 + r s / t), A = 1 / (1 + c1 r), c1 = 1/2 - 2/(3 pi),
//    s = wi.wo - cos_i cos_o, t = max(cos_i, cos_o) for s > 0 and 1 otherwise (paper eq. 3-5).
//  - Its directional albedo for rho = 1 is analytic (paper eq. 6):
//    E(mu) = A (1 + (r / pi) G(mu)), G = S (acos mu - S mu) + (2/3) ((S / mu)(1 - S^3) - S),
//    S = sqrt(1 - mu^2), with cosine-weighted average E_avg = A (1 + c2 r), c2 = 2/3 -
//    28/(15 pi) (eq. 7). The paper's fit (eq. 8, JCGT version): with m = 1 - mu,
//    G / pi ~ m (0.0571085289 + m (0.491881867 + m (-0.332181442 + m 0.0714429953))).
//  - Multiple scattering (eq. 9-10), the Kelemen / Kulla-Conty form:
//    f_ms = (rho_ms / pi) (1 - E(mu_i)) (1 - E(mu_o)) / (1 - E_avg),
//    rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)).
//    With the analytic E, single plus multiple scattering reflects everything for rho = 1 at
//    every wi. With the fit (the paper's fast path), 1 - E in f_ms differs from the true
//    loss by the fit's error, at most 4.7e-4 (measured over r, mu in [0,1]); the white albedo
//    is then 1 within 5.4e-4, and can exceed 1 by up to 1.2e-4 (r = 1, mu ~ 0.75).
//
// Sampling (paper section 5): the clipped linearly transformed cosine (CLTC) with the paper's
// fitted matrix M = [[a, 0, b], [0, c, 0], [d, 0, 1]] in the frame whose x axis is wi's
// azimuth, mixed with uniform hemisphere sampling with probability P_u(mu_i, r). A cosine-
// distributed direction w_h is drawn uniformly from the part of the projected disk whose
// image M w_h lies above the horizon (area pi (1 + 1/sqrt(1 + d^2)) / 2), so the CLTC density
// of wo = M w_h / |M w_h| is exactly
//   p(wo) = (det M / |adj(M) wo|^2)^2 max(0, [adj(M) wo]_z) / (pi s), s = (1 + 1/sqrt(1 + d^2)) / 2,
// and the mixture's pdf is exact. (The paper draws the disk region for d <= 0 only; d turns
// slightly positive near normal incidence, where the region is mirrored here so that it is
// always exactly the unclipped part.)
#pragma once

#include <optional>

#include "materials/bsdf/bsdf.h"
#include "materials/core/warp.h"

namespace scatterlab {

// Which directional albedo the multiple-scattering lobe uses.
enum class EonAlbedo { Fitted, Analytic };

namespace eon {

inline constexpr double C1 = 0.5 - 2.0 / (3.0 * Pi);
inline constexpr double C2 = 2.0 / 3.0 - 28.0 / (15.0 * Pi);

// FON's A = 1 / (1 + c1 r).
template <typename T> T fonA(const T& r) { return T(1) / (T(1) + T(C1) * r); }

// E(mu) of FON for rho = 1, analytic (eq. 6). (S / mu)(1 - S^3) is written as
// S mu (1 + S + S^2) / (1 + S), using 1 - S = mu^2 / (1 + S): finite at mu = 0, where E = 1.
template <typename T> T fonAlbedoAnalytic(double mu, const T& r) {
  mu = std::clamp(mu, 0.0, 1.0);
  const double s = std::sqrt(1.0 - mu * mu);
  const double g = s * (std::acos(mu) - s * mu) + (2.0 / 3.0) * (s * mu * (1.0 + s + s * s) / (1.0 + s) - s);
  return fonA(r) * (T(1) + r * T(g * InvPi));
}

// E(mu) by the paper's fit (eq. 8).
template <typename T> T fonAlbedoFitted(double mu, const T& r) {
  const double m = 1.0 - std::clamp(mu, 0.0, 1.0);
  const double gOverPi = m * (0.0571085289 + m * (0.491881867 + m * (-0.332181442 + m * 0.0714429953)));
  return fonA(r) * (T(1) + r * T(gOverPi));
}

// The cosine-weighted average of the analytic E (eq. 7).
template <typename T> T fonAverageAlbedo(const T& r) { return fonA(r) * (T(1) + T(C2) * r); }

template <typename T> T fonAlbedo(double mu, const T& r, EonAlbedo which) {
  return which == EonAlbedo::Analytic ? fonAlbedoAnalytic(mu, r) : fonAlbedoFitted(mu, r);
}

}  // namespace eon

// f = f_ss + f_ms (header comment), one-sided, without the cosine of wo. Geometry stays double;
// rho and r are T (fitting).
template <typename T>
RgbT<T> eonEval(const RgbT<T>& rho, const T& r, const Vec3d& wi, const Vec3d& wo, EonAlbedo which) {
  if (!(wi.z > 0) || !(wo.z > 0)) return RgbT<T>(T(0));
  const double s = glm::dot(wi, wo) - wi.z * wo.z;
  const double sOverT = s > 0 ? s / std::max(wi.z, wo.z) : s;
  const T singleFactor = T(InvPi) * eon::fonA(r) * (T(1) + r * T(sOverT));
  const T averageLoss = T(1) - eon::fonAverageAlbedo(r);
  if (!(averageLoss > T(0))) return rho * singleFactor;  // r = 0: Lambert, nothing lost
  // 1 - E of the fit dips below 0 at grazing (by < 4.7e-4, where the true value is 0).
  T lossI = T(1) - eon::fonAlbedo(wi.z, r, which), lossO = T(1) - eon::fonAlbedo(wo.z, r, which);
  if (lossI < T(0)) lossI = T(0);
  if (lossO < T(0)) lossO = T(0);
  // rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)).
  return rho * singleFactor + rho * rho * (T(1) - averageLoss) / (RgbT<T>(T(1)) - rho * averageLoss) *
                                  (T(InvPi) * lossI * lossO / averageLoss);
}

// The CLTC lobe about wi (header comment): exact sampler and density.
class EonCltc {
 public:
  EonCltc(const Vec3d& wi, double r);
  std::optional<Vec3d> sample(const Vec2d& u) const;
  double pdf(const Vec3d& wo) const;

 private:
  Vec3d x_{1, 0, 0}, y_{0, 1, 0};  // the frame's tangent axes; z is the normal
  double a_ = 1, b_ = 0, c_ = 1, d_ = 0;
  double s_ = 1;  // the unclipped share of the disk
};

class EonBsdf final : public BsdfModel {
 public:
  // rho in [0, 1] per channel, roughness in [0, 1] (the registry checks the ranges).
  EonBsdf(const Rgb& rho, double roughness, EonAlbedo albedo = EonAlbedo::Fitted)
      : rho_(rho), r_(roughness), albedo_(albedo) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return eonEval<double>(rho_, r_, wi, wo, albedo_);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override;
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection; }
  // White with the analytic albedo: lossless by construction. The fitted albedo leaves an
  // error of up to 5.4e-4 (header comment), so that variant is not claimed lossless.
  bool isLossless() const override { return rho_ == Rgb(1.0) && albedo_ == EonAlbedo::Analytic; }

  const Rgb& albedo() const { return rho_; }
  double roughness() const { return r_; }
  EonAlbedo directionalAlbedo() const { return albedo_; }
  // Probability of the uniform lobe in the sampling mixture (paper section 5.3).
  static double uniformProbability(double mu, double r);

 private:
  Rgb rho_;
  double r_;
  EonAlbedo albedo_;
};

struct MaterialModel;

// The material registry's "eon" model (materials/registry/model_list.h).
MaterialModel eonModel();

}  // namespace scatterlab
