#include "app/profile_annuli.h"

#include <algorithm>

#include "materials/core/rng.h"

namespace scatterlab {

double profileExtent(const RadialProfile& profile) {
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
    if (profile.totalReflectance()[c] > 0) largest = std::max(largest, profile.sampleRadius(c, 0.999));
  return largest > 0 ? largest : 1.0;
}

std::vector<double> annulusMeans(const RadialProfile& profile, int channel,
                                 const std::vector<double>& edges) {
  std::vector<double> means;
  const double total = profile.totalReflectance()[channel];
  for (size_t k = 0; k + 1 < edges.size(); ++k) {
    const double mass =
        total > 0 ? total * (profile.radiusCdf(channel, edges[k + 1]) - profile.radiusCdf(channel, edges[k]))
                  : 0.0;
    means.push_back(mass / (Pi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k])));
  }
  return means;
}

HalfSpaceWalkSettings mediumWalkSettings(const ScatteringMedium& medium, int channel,
                                         const std::vector<double>& edges, uint64_t paths, uint64_t seed,
                                         int threads) {
  HalfSpaceWalkSettings s;
  s.albedo = medium.albedo()[channel];
  s.extinction = medium.extinction()[channel];
  s.g = medium.g;
  s.eta = medium.eta;
  s.radiusEdges = edges;
  s.paths = paths;
  s.seed = deriveSeed(seed, uint64_t(channel));
  s.threads = threads;
  return s;
}

}  // namespace scatterlab
