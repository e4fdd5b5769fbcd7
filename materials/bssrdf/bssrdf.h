// Subsurface scattering: the radial-profile interface every diffusion model implements.
//
// Conventions (docs/design.md, "Conventions"; every profile, sampler, test and the CLI rely on them):
//  - Lengths in mm, coefficients in mm^-1 (Jensen et al. 2001), per linear-RGB channel.
//  - A medium (medium.h) is sigma_s, sigma_a, the Henyey-Greenstein g and eta, the index of
//    refraction inside relative to outside. Reduced: sigma_s' = sigma_s (1 - g),
//    sigma_t' = sigma_a + sigma_s', alpha' = sigma_s' / sigma_t'.
//  - R(r), in mm^-2, is the radiant exitance at distance r from the point where unit power
//    enters a homogeneous half-space (the searchlight configuration: the incident light
//    crossed the boundary at normal incidence; its Fresnel loss on the way in is not part of
//    R). Its integral over the plane, Rd = integral_0^inf 2 pi r R(r) dr, is the total
//    diffuse reflectance; every model has it in closed form (or as its table) in
//    totalReflectance(), and the kit checks the integral against it.
//  - The separable BSSRDF (separable_bssrdf.h) is S = Ft(wi) R(|xi - xo|) Ft(wo) / (pi c), the
//    directional term normalised so that everything R carries to the boundary leaves it.
//  - Radius sampling, per channel: r has the density pdf(r) = 2 pi r R(r) / Rd per unit radius
//    on [0, inf) (or the model's finite support). radiusCdf, radiusPdf and sampleRadius are a
//    cdf / pdf / inverse triplet of one function: sampleRadius(c, radiusCdf(c, r)) = r.
//  - Model kernels are templated on the scalar T (double, ceres::Jet): math is unqualified
//    after `using std::...`, constants are T(...), guards keep values and derivatives finite
//    (docs/design.md, "One model code"). The classes below forward to kernel<double>.
#pragma once

#include <string>

#include "materials/core/math.h"

namespace scatterlab {

class RadialProfile {
 public:
  virtual ~RadialProfile() = default;

  // "dipole", "better-dipole", "beam-diffusion", "burley".
  virtual std::string name() const = 0;

  // R(r) in mm^-2 per channel, for r >= 0 (a profile that diverges at r = 0 returns a large
  // finite value there).
  virtual Rgb eval(double r) const = 0;

  // Rd = integral_0^inf 2 pi r R(r) dr per channel, in closed form.
  virtual Rgb totalReflectance() const = 0;

  // The radius distribution of one channel (0, 1, 2), defined when totalReflectance()[channel]
  // is positive: cumulative probability of radii below r, its derivative per mm, and the
  // radius at cumulative probability u in [0, 1).
  virtual double radiusCdf(int channel, double r) const = 0;
  virtual double radiusPdf(int channel, double r) const = 0;
  virtual double sampleRadius(int channel, double u) const = 0;
};

// One radius drawn for a channel, with what a Monte Carlo estimator needs: the density and,
// per channel, the weight 2 pi r R(r) / pdf (for the sampled channel, its Rd: the sampling is
// exact).
struct RadiusSample {
  double r = 0.0;
  double pdf = 0.0;
  Rgb weight{0.0};
};

inline RadiusSample sampleRadiusWithWeight(const RadialProfile& profile, int channel, double u) {
  RadiusSample s;
  s.r = profile.sampleRadius(channel, u);
  s.pdf = profile.radiusPdf(channel, s.r);
  if (s.pdf > 0) s.weight = (2.0 * Pi * s.r / s.pdf) * profile.eval(s.r);
  return s;
}

}  // namespace scatterlab
