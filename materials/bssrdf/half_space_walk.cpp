#include "materials/bssrdf/half_space_walk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "materials/bsdf/fresnel.h"
#include "materials/bssrdf/henyey_greenstein.h"
#include "materials/core/warp.h"

namespace scatterlab {

namespace {

// The direction (propagating into the medium, z < 0) refracted from an outside direction
// propagating downward with cosine cosOutside > 0 and azimuth along (cx, cy).
Vec3d refractDown(double cosOutside, double cx, double cy, double eta) {
  const double sinOutside = safeSqrt(1.0 - cosOutside * cosOutside);
  const double sinInside = sinOutside / eta;  // outside -> inside never totally reflects
  const double cosInside = safeSqrt(1.0 - sinInside * sinInside);
  return {sinInside * cx, sinInside * cy, -cosInside};
}

Vec3d entryDirection(const HalfSpaceWalkSettings& s, CounterRng& rng) {
  if (s.incidence == WalkIncidence::Searchlight) return refractDown(s.incidentCosTheta, 1.0, 0.0, s.eta);
  // Diffuse: cosine-weighted outside; what enters is weighted by the transmittance 1 - F.
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const Vec3d w = sampleCosineHemisphere(rng.uniform2D());
    const double sinTheta = safeSqrt(1.0 - w.z * w.z);
    const double cx = sinTheta > 0 ? -w.x / sinTheta : 1.0, cy = sinTheta > 0 ? -w.y / sinTheta : 0.0;
    if (s.eta == 1.0 || rng.uniform() >= fresnelDielectric(w.z, s.eta))
      return refractDown(w.z, cx, cy, s.eta);
  }
  return {0.0, 0.0, -1.0};  // unreachable: the mean transmittance is > 0.5 for eta in (0, 4]
}

}  // namespace

void HalfSpaceWalkSettings::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("half-space walk: " + what); };
  if (!(albedo >= 0 && albedo <= 1)) fail("the albedo must be in [0, 1]");
  if (!(extinction > 0) || !std::isfinite(extinction)) fail("sigma_t must be positive and finite");
  if (!(g > -1 && g < 1)) fail("g must be in (-1, 1)");
  if (!(eta > 0) || !std::isfinite(eta)) fail("eta must be positive and finite");
  if (incidence == WalkIncidence::Searchlight && !(incidentCosTheta > 0 && incidentCosTheta <= 1))
    fail("the incident cosine must be in (0, 1]");
  if (paths == 0) fail("at least one path is needed");
  if (radiusEdges.size() == 1 || (!radiusEdges.empty() && radiusEdges.front() != 0.0))
    fail("radius edges must start at 0 and hold at least one annulus");
  for (size_t k = 1; k < radiusEdges.size(); ++k)
    if (!(radiusEdges[k] > radiusEdges[k - 1]) || !std::isfinite(radiusEdges[k]))
      fail("radius edges must increase");
  if (threads < 0) fail("the thread count must be >= 0");
}

WalkPath traceHalfSpacePath(const HalfSpaceWalkSettings& s, CounterRng& rng) {
  WalkPath path;
  Vec3d position(0.0), direction = entryDirection(s, rng);
  const double insideOut = 1.0 / s.eta;  // relative index for light leaving the medium
  // However the path ends, a position that is no longer finite marks it (header comment).
  const auto end = [&]() -> WalkPath& {
    path.nonFinite = !isFinite(position);
    return path;
  };
  for (;;) {
    const double distance = -std::log1p(-rng.uniform()) / s.extinction;
    if (direction.z > 0 && position.z + distance * direction.z >= 0.0) {
      position += (-position.z / direction.z) * direction;
      position.z = 0.0;
      // Exponential free paths are memoryless: after a reflection the walk draws afresh.
      if (s.eta != 1.0 && rng.uniform() < fresnelDielectric(direction.z, insideOut)) {
        direction.z = -direction.z;
        continue;
      }
      path.escaped = true;
      path.exitRadius = std::hypot(position.x, position.y);
      return end();
    }
    position += distance * direction;
    if (rng.uniform() >= s.albedo) return end();  // absorbed
    if (++path.scatteringEvents >= s.maxScatteringEvents) {
      path.truncated = true;
      return end();
    }
    direction = glm::normalize(sampleHenyeyGreenstein(direction, s.g, rng.uniform2D()));
  }
}

void HalfSpaceTally::add(const WalkPath& path, const std::vector<double>& radiusEdges) {
  scatteringEvents += path.scatteringEvents;
  if (path.nonFinite) {
    ++nonFinite;
  } else if (path.truncated) {
    ++truncated;
  } else if (!path.escaped) {
    ++absorbed;
  } else {
    ++escaped;
    const bool single = path.scatteringEvents == 1;
    singleEscaped += single;
    const size_t k = size_t(std::upper_bound(radiusEdges.begin(), radiusEdges.end(), path.exitRadius) -
                            radiusEdges.begin());
    if (k >= 1 && k <= counts.size()) {
      ++counts[k - 1];
      singleCounts[k - 1] += single;
    }
  }
}

void HalfSpaceTally::merge(const HalfSpaceTally& other) {
  escaped += other.escaped;
  absorbed += other.absorbed;
  truncated += other.truncated;
  nonFinite += other.nonFinite;
  scatteringEvents += other.scatteringEvents;
  singleEscaped += other.singleEscaped;
  for (size_t k = 0; k < counts.size(); ++k) {
    counts[k] += other.counts[k];
    singleCounts[k] += other.singleCounts[k];
  }
}

void traceHalfSpacePaths(const HalfSpaceWalkSettings& settings, uint64_t first, uint64_t last,
                         HalfSpaceTally& tally) {
  for (uint64_t i = first; i < last; ++i) {
    CounterRng rng(settings.seed, i);
    tally.add(traceHalfSpacePath(settings, rng), settings.radiusEdges);
  }
}

HalfSpaceWalkResult halfSpaceWalkResult(const HalfSpaceWalkSettings& settings, const HalfSpaceTally& tally) {
  const std::vector<double>& edges = settings.radiusEdges;
  HalfSpaceWalkResult result;
  result.settings = settings;
  result.escaped = tally.escaped;
  result.absorbed = tally.absorbed;
  result.truncated = tally.truncated;
  result.nonFinite = tally.nonFinite;
  result.scatteringEvents = tally.scatteringEvents;
  result.counts = tally.counts;
  result.singleCounts = tally.singleCounts;
  result.singleEscaped = tally.singleEscaped;
  const double n = double(settings.paths);
  const auto proportion = [n](uint64_t count) {
    const double p = double(count) / n;
    return std::pair{p, std::sqrt(p * (1.0 - p) / n)};
  };
  std::tie(result.totalReflectance, result.totalStdError) = proportion(result.escaped);
  std::tie(result.singleReflectance, result.singleStdError) = proportion(result.singleEscaped);
  for (size_t k = 0; k < result.counts.size(); ++k) {
    const double area = Pi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k]);
    const auto [pk, se] = proportion(result.counts[k]);
    result.profile.push_back(pk / area);
    result.profileStdError.push_back(se / area);
  }
  return result;
}

std::vector<double> HalfSpaceWalkResult::multipleScatteringProfile() const {
  const std::vector<double>& edges = settings.radiusEdges;
  std::vector<double> out;
  for (size_t k = 0; k < counts.size(); ++k)
    out.push_back(double(counts[k] - singleCounts[k]) / double(settings.paths) /
                  (Pi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k])));
  return out;
}

std::vector<double> logRadiusEdges(double first, double last, int n) {
  if (!(first > 0) || !(last > first) || n < 2)
    throw std::invalid_argument("logRadiusEdges: need 0 < first < last, n >= 2");
  std::vector<double> edges{0.0};
  for (int k = 0; k < n; ++k) edges.push_back(first * std::pow(last / first, double(k) / (n - 1)));
  return edges;
}

std::vector<double> linearRadiusEdges(double last, int n) {
  if (!(last > 0) || n < 1) throw std::invalid_argument("linearRadiusEdges: need last > 0, n >= 1");
  std::vector<double> edges{0.0};
  for (int k = 1; k <= n; ++k) edges.push_back(last * double(k) / double(n));
  return edges;
}

}  // namespace scatterlab
