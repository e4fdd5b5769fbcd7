// Counting samples into the cells of any binning, for the chi-square tests that are not over
// the sphere of directions (the 1-D radius test and the planar probe test, docs/validation.md
// section 6). Sample i draws from CounterRng(seed, i) and the counts are integers, so the
// result is the same for any number of threads (TBB).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "materials/core/rng.h"

namespace scatterlab {

// What one draw produced: the cell it fell into, nothing (the sampler failed: legal, it
// reduces the mass), or a broken rule (`invalid` says which: always a test failure).
struct CellDraw {
  int cell = -1;  // -1 with invalid == nullptr: the sampler failed
  const char* invalid = nullptr;
  static CellDraw failed() { return {}; }
};

struct CellCounts {
  std::vector<uint64_t> counts;
  size_t failed = 0;
  size_t invalid = 0;
  std::string firstInvalid;  // the lowest-index invalid sample, described
};

// `draw(CounterRng&) -> CellDraw`, with cells in [0, cellCount).
template <typename DrawFn>
CellCounts countSamples(int cellCount, size_t n, uint64_t seed, const DrawFn& draw) {
  struct Part {
    std::vector<uint64_t> counts;
    size_t failed = 0, invalid = 0, firstInvalidIndex = SIZE_MAX;
    std::string firstInvalid;
  };
  tbb::enumerable_thread_specific<Part> parts([cellCount] {
    Part p;
    p.counts.assign(size_t(cellCount), 0);
    return p;
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
    Part& part = parts.local();
    for (size_t i = range.begin(); i != range.end(); ++i) {
      CounterRng rng(seed, i);
      const CellDraw d = draw(rng);
      const char* why =
          d.invalid ? d.invalid : (d.cell >= cellCount ? "sample outside the binning" : nullptr);
      if (why) {
        ++part.invalid;
        if (i < part.firstInvalidIndex) {
          part.firstInvalidIndex = i;
          part.firstInvalid = std::string(why) + " (sample " + std::to_string(i) + ")";
        }
      } else if (d.cell < 0) {
        ++part.failed;
      } else {
        ++part.counts[size_t(d.cell)];
      }
    }
  });
  CellCounts total;
  total.counts.assign(size_t(cellCount), 0);
  size_t firstIndex = SIZE_MAX;
  for (const Part& part : parts) {
    for (size_t c = 0; c < total.counts.size(); ++c) total.counts[c] += part.counts[c];
    total.failed += part.failed;
    total.invalid += part.invalid;
    if (part.firstInvalidIndex < firstIndex) {
      firstIndex = part.firstInvalidIndex;
      total.firstInvalid = part.firstInvalid;
    }
  }
  return total;
}

}  // namespace scatterlab
