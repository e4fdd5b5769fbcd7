// Deliberately wrong subsurface samplers (docs/validation.md section 1, "Power", for section 6):
// each is self-consistent in everything but the one claim the chi-square test is there to
// check, and the kit must reject it.
//  - RadiusPdfHighOnHalf: radiusPdf() 5% too high below each channel's median radius; the
//    radii are drawn as before (the 1-D radius test must see it).
//  - WrongChannelWeights: the probe pdf sums the channels with weights 30% off the ones the
//    sampler chooses channels with (the 2-D probe test must see it).
//  - RadialShortcut: the probe pdf as if every exit point had come from the normal axis' disk
//    at its distance, sum_c P_c p_c(|xo - xi|) / (2 pi |xo - xi|), instead of the exact
//    multi-axis sum over projected radii (the 2-D probe test, tilted frame, must see it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "materials/bssrdf/probe_sampling.h"

namespace scatterlab {

enum class SubsurfaceControl { RadiusPdfHighOnHalf, WrongChannelWeights, RadialShortcut };
std::string toString(SubsurfaceControl control);
std::vector<SubsurfaceControl> allSubsurfaceControls();

class RadiusPdfHighOnHalf final : public RadialProfile {
 public:
  explicit RadiusPdfHighOnHalf(const RadialProfile& profile);
  std::string name() const override { return profile_.name() + " (pdf +5% below the median)"; }
  Rgb eval(double r) const override { return profile_.eval(r); }
  Rgb totalReflectance() const override { return profile_.totalReflectance(); }
  double radiusCdf(int c, double r) const override { return profile_.radiusCdf(c, r); }
  double radiusPdf(int c, double r) const override {
    return profile_.radiusPdf(c, r) * (r < median_[size_t(c)] ? 1.05 : 1.0);
  }
  double sampleRadius(int c, double u) const override { return profile_.sampleRadius(c, u); }

 private:
  const RadialProfile& profile_;
  std::vector<double> median_;
};

// The channel weights the WrongChannelWeights pdf claims: P_c (1 + 0.3 (c - 1)) over the
// reflecting channels, renormalised.
ProbeSampling skewedChannelWeights(const ProbeSampling& sampling);

// Why a control cannot be told apart from the correct sampler for this profile (the wrong
// weights change nothing when every reflecting channel has the same radius distribution, or
// only one channel reflects), or nothing when it can.
std::optional<std::string> subsurfaceControlIsNoOp(SubsurfaceControl control, const RadialProfile& profile,
                                                   const ProbeSampling& sampling);

// The radial-shortcut density at the plane point p (entry point at the origin).
double radialShortcutPdf(const ProbeSampler& sampler, const Vec2d& p);

}  // namespace scatterlab
