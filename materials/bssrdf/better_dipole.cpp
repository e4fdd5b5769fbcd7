#include "materials/bssrdf/better_dipole.h"

#include "materials/bsdf/fresnel_moments.h"

namespace scatterlab {

FresnelBoundary fresnelBoundary(double eta) {
  const double c1 = fresnelMoment(1, 1.0 / eta), c2 = fresnelMoment(2, 1.0 / eta);
  return {(1.0 + 3.0 * c2) / (1.0 - 2.0 * c1), 0.25 * (1.0 - 2.0 * c1), 0.5 * (1.0 - 3.0 * c2)};
}

BetterDipoleProfile::BetterDipoleProfile(const Rgb& sigmaSPrime, const Rgb& sigmaA, double eta) {
  const FresnelBoundary boundary = fresnelBoundary(eta);
  Rgb total, meanFreePath;
  for (int c = 0; c < 3; ++c) {
    channels_[c] = makeBetterDipole(sigmaSPrime[c], sigmaA[c], boundary);
    total[c] = betterDipoleTotal(channels_[c]);
    meanFreePath[c] = channels_[c].zr;
  }
  prepareSampling(total, meanFreePath);
}

}  // namespace scatterlab
