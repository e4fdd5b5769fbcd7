// A subsurface profile on annuli, next to the half-space random walk: the numbers `scatterlab
// profile` prints and the lab report's subsurface section plots. R(r) is averaged over each
// annulus exactly (from the profile's CDF), which is what the walk's tallies estimate, so the
// two are compared like for like.
#pragma once

#include <cstdint>
#include <vector>

#include "materials/bssrdf/bssrdf.h"
#include "materials/bssrdf/half_space_walk.h"
#include "materials/bssrdf/medium.h"

namespace scatterlab {

// The radius where every reflecting channel holds 99.9% of its profile (1 mm when none
// reflects): the default outer edge of the annuli.
double profileExtent(const RadialProfile& profile);

// R averaged over each annulus [edges[k], edges[k + 1]]: Rd (cdf(r1) - cdf(r0)) / (pi (r1^2 - r0^2)).
std::vector<double> annulusMeans(const RadialProfile& profile, int channel, const std::vector<double>& edges);

// The walk in `medium`'s channel (its albedo, extinction, g and eta), tallied on `edges`;
// channel c's paths use the seed deriveSeed(seed, c).
HalfSpaceWalkSettings mediumWalkSettings(const ScatteringMedium& medium, int channel,
                                         const std::vector<double>& edges, uint64_t paths, uint64_t seed,
                                         int threads);

}  // namespace scatterlab
