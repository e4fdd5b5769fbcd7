#include "app/walk_estimate.h"

#include <algorithm>
#include <chrono>

#include "validation/half_space_reference.h"

namespace scatterlab {

namespace {

// Seconds per path of `walk`, from a pilot of its own kind of paths (another seed) in batches
// that double until they have taken PilotSeconds or reached a hundredth of the walk. A time
// budget rather than a path count: near albedo 1 one path may scatter millions of times, and
// a pilot of a fixed count could itself take minutes.
double secondsPerPath(const HalfSpaceWalkSettings& walk) {
  constexpr double PilotSeconds = 0.3;
  HalfSpaceWalkSettings pilot = walk;
  uint64_t done = 0;
  double spent = 0.0;
  for (uint64_t batch = 32; spent < PilotSeconds && done < walk.paths / 100; batch *= 2) {
    pilot.paths = batch;
    pilot.seed = walk.seed ^ (0x9E3779B97F4A7C15ull + batch);  // not the run's own paths
    const auto start = std::chrono::steady_clock::now();
    simulateHalfSpace(pilot);
    spent += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    done += batch;
  }
  return spent / double(std::max<uint64_t>(done, 1));
}

}  // namespace

WorkEstimate estimateWalks(const std::string& what, const std::vector<HalfSpaceWalkSettings>& walks) {
  // Walks of fewer paths take seconds at most: not worth a pilot.
  constexpr uint64_t PilotAbovePaths = 100'000;
  WorkEstimate estimate{what, 0.0, 0.0};
  for (const HalfSpaceWalkSettings& walk : walks) {
    // The process itself (~30 MB), and a tally of two counters per annulus for each of at most
    // a few hundred parallel tasks (half_space_walk.h): the walk streams its paths.
    estimate.bytes = std::max(estimate.bytes, 30e6 + 256.0 * 16.0 * double(walk.radiusEdges.size()));
    if (walk.paths > PilotAbovePaths) estimate.seconds += secondsPerPath(walk) * double(walk.paths);
  }
  return estimate;
}

}  // namespace scatterlab
