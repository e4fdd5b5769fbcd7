// Multiple-scattering energy compensation of a microfacet reflector (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks", SIGGRAPH course; after Kelemen &
// Szirmay-Kalos 2001). Single scattering with F = 1 returns E(mu_i) of the light
// (white_microfacet_albedo.h); the rest, 1 - E(mu_i), leaves after more bounces between
// microfacets. The compensation lobe
//   f_ms(wi, wo) = (1 - E(wi)) (1 - E(wo)) / (pi (1 - E_avg)),
//   E_avg = (1/pi) integral of E(w) cos theta dw,
// is symmetric in wi and wo (reciprocal) and reflects exactly 1 - E(wi), since
// integral of (1 - E(wo)) cos_o dwo = pi (1 - E_avg); so single scattering plus f_ms returns
// all the light a perfect reflector receives, at every wi. A coloured conductor loses a
// fraction of the light at each bounce; with the cosine-weighted average Fresnel F_avg
// (fresnel_average.h), summing the bounces as a geometric series gives the factor
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
// which is 1 for F = 1 and saturates the colour of rough metals.
//
// Sampling. In wo the lobe is (1 - E(wo)) cos_o, which for small roughness is concentrated at
// grazing directions (where masking acts): cosine sampling would be exact but would give
// weights up to 1e5 there. The lobe is sampled instead from a tabulated density close to it,
// exactly (LossLobeSampler, shared with the rough dielectric's compensation): a bilinear
// density (PiecewiseBilinear2D) over (phi, v), v = sqrt(t) with t the table's Moebius
// coordinate of mu (white_microfacet_albedo.h), whose vertex values are (1 - E) mu dmu/dv
// plus 5% of a cosine lobe, so that it is positive wherever f_ms is. Its pdf per solid angle
// is the bilinear density divided by dmu/dv, exact by construction.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "materials/bsdf/white_microfacet_albedo.h"
#include "materials/core/math.h"
#include "materials/core/piecewise_bilinear.h"

namespace scatterlab {

// Light that scatters more than once between microfacets: lost (the published single-scattering
// models), or returned by a Kulla & Conty 2017 lobe (the conductor's below, the rough
// dielectric's in rough_dielectric_multiscatter.h).
enum class MultipleScattering { None, KullaConty };

// f_ms for F = 1 from the losses 1 - E(wi), 1 - E(wo) and 1 - E_avg; 0 when nothing is lost
// on average (then nothing is lost at any direction either).
template <typename T> T kullaContyLobe(const T& lossI, const T& lossO, const T& averageLoss) {
  if (!(averageLoss > T(0))) return T(0);
  return lossI * lossO / (T(Pi) * averageLoss);
}

// F_ms per channel.
template <typename T> RgbT<T> kullaContyFresnel(const RgbT<T>& fresnelAverage, const T& averageAlbedo) {
  const RgbT<T> one(T(1));
  return fresnelAverage * fresnelAverage * averageAlbedo / (one - fresnelAverage * (T(1) - averageAlbedo));
}

// Directions above the surface drawn from a tabulated density close to loss(w) cos theta, with
// its exact pdf (the header comment): the sampler of a compensation lobe whose shape in wo is
// (1 - E(wo)) cos_o. `loss` is read at the table's vertices during construction only;
// `averageLoss` = (1/pi) integral of loss cos sets the cosine share; alphaX, alphaY place the
// vertices where masking changes E (on the scale mu ~ alpha).
class LossLobeSampler {
 public:
  LossLobeSampler() = default;
  LossLobeSampler(const std::function<double(const Vec3d&)>& loss, double averageLoss, double alphaX,
                  double alphaY);

  // A direction above the surface (nothing on the measure-zero rim), and its density per solid
  // angle; pdf is 0 for wo.z <= 0.
  std::optional<Vec3d> sample(const Vec2d& u) const;
  double pdf(const Vec3d& wo) const;

  static constexpr int CosNodes = 65;                 // v nodes
  static constexpr int AnisotropicAzimuthNodes = 65;  // phi nodes over [0, 2 pi]
  static constexpr double CosineShare = 0.05;         // of the sampling density's mass

 private:
  // The Moebius scale's roughness along the azimuth phi.
  double projectedAlpha(double cosPhi, double sinPhi) const;

  double alphaX_ = 1.0, alphaY_ = 1.0;
  PiecewiseBilinear2D density_;  // over (phi in [0, 2 pi], v in [0, 1])
};

// The compensation lobe of one distribution and roughness with F = 1: its value, and a sampler
// of wo with an exact pdf close to the lobe's shape in wo.
class KullaContyLobe {
 public:
  explicit KullaContyLobe(std::shared_ptr<const WhiteMicrofacetAlbedo> albedo);

  const WhiteMicrofacetAlbedo& albedo() const { return *albedo_; }
  // f_ms(wi, wo) for F = 1; 0 unless both directions are above the surface.
  double eval(const Vec3d& wi, const Vec3d& wo) const {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    return kullaContyLobe(albedo_->loss(wi), albedo_->loss(wo), albedo_->averageLoss());
  }
  // See LossLobeSampler.
  std::optional<Vec3d> sample(const Vec2d& u) const { return sampler_.sample(u); }
  double pdf(const Vec3d& wo) const { return sampler_.pdf(wo); }

  static constexpr int CosNodes = LossLobeSampler::CosNodes;
  static constexpr int AnisotropicAzimuthNodes = LossLobeSampler::AnisotropicAzimuthNodes;
  static constexpr double CosineShare = LossLobeSampler::CosineShare;

 private:
  std::shared_ptr<const WhiteMicrofacetAlbedo> albedo_;
  LossLobeSampler sampler_;
};

}  // namespace scatterlab
