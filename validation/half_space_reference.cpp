#include "validation/half_space_reference.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace scatterlab {

namespace {
// Paths per unit of parallel work (and per progress report).
constexpr uint64_t ChunkPaths = 1024;
}  // namespace

HalfSpaceWalkResult simulateHalfSpace(const HalfSpaceWalkSettings& settings, const WalkProgress& progress) {
  settings.validate();
  const size_t annuli = settings.radiusEdges.empty() ? 0 : settings.radiusEdges.size() - 1;
  const uint64_t chunks = (settings.paths + ChunkPaths - 1) / ChunkPaths;
  tbb::enumerable_thread_specific<HalfSpaceTally> tallies([annuli] { return HalfSpaceTally(annuli); });
  std::atomic<uint64_t> done{0};
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<uint64_t>(0, chunks, 1), [&](const tbb::blocked_range<uint64_t>& range) {
          HalfSpaceTally& tally = tallies.local();
          for (uint64_t chunk = range.begin(); chunk != range.end(); ++chunk) {
            const uint64_t first = chunk * ChunkPaths, last = std::min(first + ChunkPaths, settings.paths);
            traceHalfSpacePaths(settings, first, last, tally);
            const uint64_t finished = done.fetch_add(last - first) + (last - first);
            if (progress) progress(double(finished) / double(settings.paths));
          }
        });
  });
  // Integer sums: the same whatever the threads' order.
  HalfSpaceTally total(annuli);
  for (const HalfSpaceTally& t : tallies) total.merge(t);
  return halfSpaceWalkResult(settings, total);
}

}  // namespace scatterlab
