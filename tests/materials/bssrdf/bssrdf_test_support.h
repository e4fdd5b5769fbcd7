// Shared by the subsurface tests: media of Jensen et al. 2001's table and a profile's energy by
// quadrature.
#pragma once

#include <memory>
#include <string>

#include "materials/bssrdf/measured_media.h"
#include "materials/bssrdf/subsurface_material.h"
#include "validation/radial_chi_square.h"

namespace scatterlab::testing_support {

inline ScatteringMedium measuredMedium(const std::string& name, double g = 0.0) {
  const MeasuredMedium* m = findMeasuredMedium(name);
  ScatteringMedium medium;
  medium.sigmaS = m->sigmaSPrime / (1.0 - g);
  medium.sigmaA = m->sigmaA;
  medium.g = g;
  medium.eta = m->eta;
  return medium;
}

// integral_0^inf 2 pi r R(r) dr of one channel, by adaptive quadrature in ln r (relative
// 1e-9) between the channel's octiles, up to where it keeps 1e-12 of its distribution.
inline double profileEnergy(const RadialProfile& profile, int channel) {
  return integrateAlongQuantiles([&](double r) { return 2.0 * Pi * r * profile.eval(r)[channel]; },
                                 [&](double u) { return profile.sampleRadius(channel, u); });
}

}  // namespace scatterlab::testing_support
