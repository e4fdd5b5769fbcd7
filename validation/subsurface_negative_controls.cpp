#include "validation/subsurface_negative_controls.h"

#include <cmath>

namespace scatterlab {

std::string toString(SubsurfaceControl control) {
  switch (control) {
    case SubsurfaceControl::RadiusPdfHighOnHalf: return "radius pdf +5% on half";
    case SubsurfaceControl::WrongChannelWeights: return "wrong channel weights";
    case SubsurfaceControl::RadialShortcut: return "radial shortcut pdf";
  }
  return "unknown";
}

std::vector<SubsurfaceControl> allSubsurfaceControls() {
  return {SubsurfaceControl::RadiusPdfHighOnHalf, SubsurfaceControl::WrongChannelWeights,
          SubsurfaceControl::RadialShortcut};
}

RadiusPdfHighOnHalf::RadiusPdfHighOnHalf(const RadialProfile& profile) : profile_(profile) {
  const Rgb total = profile.totalReflectance();
  for (int c = 0; c < 3; ++c) median_.push_back(total[c] > 0 ? profile.sampleRadius(c, 0.5) : 0.0);
}

ProbeSampling skewedChannelWeights(const ProbeSampling& sampling) {
  ProbeSampling skewed = sampling;
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    skewed.channelProbability[c] = sampling.channelProbability[c] * (1.0 + 0.3 * (c - 1));
    sum += skewed.channelProbability[c];
  }
  for (double& p : skewed.channelProbability) p /= sum;
  return skewed;
}

std::optional<std::string> subsurfaceControlIsNoOp(SubsurfaceControl control, const RadialProfile& profile,
                                                   const ProbeSampling& sampling) {
  if (control != SubsurfaceControl::WrongChannelWeights) return std::nullopt;
  std::vector<int> reflecting;
  for (int c = 0; c < 3; ++c)
    if (sampling.channelProbability[c] > 0) reflecting.push_back(c);
  if (reflecting.size() < 2) return "only one channel reflects: there are no channel weights to get wrong";
  // Same radius distribution in every channel: compare the CDFs at a spread of quantiles.
  for (double u : {0.05, 0.25, 0.5, 0.75, 0.95, 0.999}) {
    const double r = profile.sampleRadius(reflecting[0], u);
    for (int c : reflecting)
      if (std::abs(profile.radiusCdf(c, r) - u) > 1e-6) return std::nullopt;
  }
  return "every reflecting channel has the same radius distribution: channel weights change nothing";
}

double radialShortcutPdf(const ProbeSampler& sampler, const Vec2d& p) {
  const double rho = std::hypot(p.x, p.y);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += sampler.sampling().channelProbability[c] * sampler.diskDensity(c, rho);
  return sum;
}

}  // namespace scatterlab
