#include "materials/bssrdf/beam_diffusion_profile.h"

#include <algorithm>

namespace scatterlab {

namespace {
// The exitance diverges like 1/r at r = 0 (single scattering straight above the beam): radii
// below this many mean free paths are evaluated there, so eval stays finite.
constexpr double SmallestOpticalRadius = 1e-12;
}  // namespace

BeamDiffusionProfile::BeamDiffusionProfile(const ScatteringMedium& medium)
    : table_(BeamDiffusionTable::shared(medium.g, medium.eta)) {
  medium.validate();
  const Rgb albedo = medium.albedo();
  sigmaT_ = medium.extinction();
  for (int c = 0; c < 3; ++c) {
    cdf_[c] = table_->profileAt(albedo[c]);
    total_[c] = cdf_[c].total();
  }
}

Rgb BeamDiffusionProfile::eval(double r) const {
  Rgb out;
  for (int c = 0; c < 3; ++c) {
    const double optical = std::max(r * sigmaT_[c], SmallestOpticalRadius);
    out[c] = sigmaT_[c] * sigmaT_[c] * cdf_[c].density(optical) / (2.0 * Pi * optical);
  }
  return out;
}

double BeamDiffusionProfile::radiusCdf(int channel, double r) const {
  if (!(r > 0) || !(total_[channel] > 0)) return 0.0;
  return std::clamp(cdf_[channel].cumulative(r * sigmaT_[channel]) / total_[channel], 0.0, 1.0);
}

double BeamDiffusionProfile::radiusPdf(int channel, double r) const {
  if (!(r >= 0) || !(total_[channel] > 0)) return 0.0;
  return sigmaT_[channel] * cdf_[channel].density(r * sigmaT_[channel]) / total_[channel];
}

double BeamDiffusionProfile::sampleRadius(int channel, double u) const {
  return cdf_[channel].invert(u * total_[channel]) / sigmaT_[channel];
}

}  // namespace scatterlab
