// The ground truth of every diffusion profile: a volumetric random walk (analog Monte Carlo)
// in a homogeneous half-space z < 0, boundary z = 0 (docs/validation.md section 6).
//
// Light enters at the origin: the searchlight (a beam at incidence cos theta, refracted by
// Snell's law when eta != 1), or diffuse light (cosine-weighted outside, refracted, and kept
// with the Fresnel transmittance, by rejection). Results are per unit power that has crossed
// the boundary, as R(r) in bssrdf.h. Inside, free paths are exponential with sigma_t, each
// collision scatters with probability c = sigma_s / sigma_t by Henyey-Greenstein with g and
// absorbs otherwise. At the boundary the path leaves with probability 1 - F (exact Fresnel
// from inside, total internal reflection included) and is specularly reflected otherwise;
// with eta = 1 (index-matched) it always leaves. Every path counts 0 or 1, so the total
// reflectance is a binomial proportion and each annulus of R(r) a multinomial one: their
// standard errors are exact. Paths that leave after exactly one scattering event are also
// tallied on their own (single scattering), so that a profile of multiple scattering only
// (the dipoles') can be compared with the rest.
//
// Path i draws from CounterRng(seed, i) and the tallies are integers, so the result is the
// same for any number of threads. This file holds one path and the tally; the parallel driver
// over many paths, simulateHalfSpace, is validation/half_space_reference.h (materials stays free
// of threading, docs/design.md, "Who may include whom").
#pragma once

#include <cstdint>
#include <vector>

#include "materials/core/rng.h"

namespace scatterlab {

enum class WalkIncidence { Searchlight, Diffuse };

struct HalfSpaceWalkSettings {
  double albedo = 0.8;      // single-scattering albedo c = sigma_s / sigma_t, in [0, 1]
  double extinction = 1.0;  // sigma_t, mm^-1 (> 0); lengths scale as 1 / sigma_t
  double g = 0.0;           // Henyey-Greenstein mean cosine, in (-1, 1)
  double eta = 1.0;         // index of refraction inside relative to outside; 1: index-matched
  WalkIncidence incidence = WalkIncidence::Searchlight;
  double incidentCosTheta = 1.0;  // searchlight, outside, in (0, 1]
  // Annuli of R(r): increasing edges in mm from 0; paths leaving beyond the last edge count in
  // the total only.
  std::vector<double> radiusEdges{};
  uint64_t paths = 1'000'000;
  uint64_t seed = 1;
  // A path that has scattered this often is stopped and counted as `truncated` (a bias of at
  // most truncated / paths; only a medium that absorbs nothing gets near it).
  uint64_t maxScatteringEvents = uint64_t(1) << 24;
  int threads = 0;  // TBB worker threads; 0: all cores (the result does not depend on it)

  // Throws std::invalid_argument naming the setting that is out of range.
  void validate() const;
};

struct HalfSpaceWalkResult {
  HalfSpaceWalkSettings settings;
  uint64_t escaped = 0, absorbed = 0, truncated = 0;
  uint64_t scatteringEvents = 0;  // over all paths
  double totalReflectance = 0.0, totalStdError = 0.0;
  std::vector<uint64_t> counts;  // escaped paths per annulus
  std::vector<double> profile;   // R per annulus, mm^-2: counts / (paths * annulus area)
  std::vector<double> profileStdError;
  // The part of the above that scattered exactly once.
  uint64_t singleEscaped = 0;
  double singleReflectance = 0.0, singleStdError = 0.0;
  std::vector<uint64_t> singleCounts;

  // R per annulus of the paths that scattered at least twice: (counts - singleCounts) /
  // (paths * annulus area).
  std::vector<double> multipleScatteringProfile() const;
};

// One path's outcome (exposed for tests and benchmarks).
struct WalkPath {
  bool escaped = false;
  bool truncated = false;
  double exitRadius = 0.0;  // mm from the entry point, when escaped
  uint64_t scatteringEvents = 0;
};
WalkPath traceHalfSpacePath(const HalfSpaceWalkSettings& settings, CounterRng& rng);

// Integer counts of a set of paths: merged in any order, they give the same result.
struct HalfSpaceTally {
  std::vector<uint64_t> counts;        // escaped paths per annulus of the settings' radius edges
  std::vector<uint64_t> singleCounts;  // those of them that scattered exactly once
  uint64_t escaped = 0, absorbed = 0, truncated = 0, scatteringEvents = 0, singleEscaped = 0;

  explicit HalfSpaceTally(size_t annuli = 0) : counts(annuli, 0), singleCounts(annuli, 0) {}
  void add(const WalkPath& path, const std::vector<double>& radiusEdges);
  void merge(const HalfSpaceTally& other);
};

// Traces paths [first, last) of the settings (path i from CounterRng(seed, i)) into the tally.
void traceHalfSpacePaths(const HalfSpaceWalkSettings& settings, uint64_t first, uint64_t last,
                         HalfSpaceTally& tally);

// Total reflectance and R(r) per annulus with their binomial standard errors, from the tally
// of all settings.paths paths.
HalfSpaceWalkResult halfSpaceWalkResult(const HalfSpaceWalkSettings& settings, const HalfSpaceTally& tally);

// n + 1 edges: 0, then n log-spaced edges from `first` to `last` (mm).
std::vector<double> logRadiusEdges(double first, double last, int n);
// n + 1 edges: 0, last / n, 2 last / n, ..., last (mm).
std::vector<double> linearRadiusEdges(double last, int n);

}  // namespace scatterlab
