#include "validation/probe_plane.h"

#include <algorithm>
#include <cmath>

#include "materials/core/root_finding.h"

namespace scatterlab {

const char* toString(ProbeFrame frame) { return frame == ProbeFrame::Aligned ? "aligned" : "tilted"; }

Framed probeFrame(ProbeFrame frame) {
  if (frame == ProbeFrame::Aligned) return Framed();
  return Framed::fromNormal(glm::normalize(Vec3d(0.3, 0.4, 0.866)));
}

std::optional<Vec2d> probeExitOnPlane(const ProbeSampler& sampler, const Framed& frame, CounterRng& rng) {
  const double uChoice = rng.uniform();
  const ProbeSegment segment = sampler.sample(frame, Vec3d(0.0), uChoice, rng.uniform2D());
  const double z0 = segment.start.z, z1 = segment.end.z;
  // The chord meets z = 0 where its end points' heights change sign (a chord lying in the
  // plane, z0 = z1 = 0, has measure zero).
  if (!(z0 != z1) || (z0 > 0) == (z1 > 0)) return std::nullopt;
  const double t = z0 / (z0 - z1);
  const Vec3d hit = segment.start + t * (segment.end - segment.start);
  return Vec2d(hit.x, hit.y);
}

double probeExitPdfOnPlane(const ProbeSampler& sampler, const Framed& frame, const Vec2d& p) {
  return sampler.pdf(frame, Vec3d(0.0), Vec3d(p.x, p.y, 0.0), Vec3d(0.0, 0.0, 1.0));
}

PolarGrid probePolarGrid(const ProbeSampler& sampler, const RadialProfile& profile, int rings, int sectors) {
  const ProbeSampling& s = sampler.sampling();
  const double outer = sampler.largestRadius();
  auto mixture = [&](double rho) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
      if (s.channelProbability[c] > 0)
        sum += s.channelProbability[c] * std::min(profile.radiusCdf(c, rho) / s.truncation, 1.0);
    return sum;
  };
  std::vector<double> edges{0.0, outer};
  for (int k = 1; k < rings; ++k)
    edges.push_back(bisectIncreasing(mixture, double(k) / rings, 0.0, outer, 1e-12 * outer));
  for (int c = 0; c < 3; ++c)
    if (s.channelProbability[c] > 0) edges.push_back(sampler.maxRadius(c));
  std::sort(edges.begin(), edges.end());
  PolarGrid grid;
  grid.sectors = sectors;
  for (double e : edges)
    if (grid.ringEdges.empty() || e > grid.ringEdges.back() * (1.0 + 1e-9) + 1e-300)
      grid.ringEdges.push_back(e);
  return grid;
}

}  // namespace scatterlab
