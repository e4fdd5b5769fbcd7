// The random numbers of one camera sample: a pure function of (seed, pixel, sample index), so
// an image is the same whatever the number of threads and however the tiles are scheduled.
// The project's counter-based generator (materials/core/rng.h, Philox4x32-10) is keyed by the
// seed; its stream is the pixel index in the high 32 bits and the sample index in the low 32.
#pragma once

#include <cstdint>

#include "materials/core/rng.h"

namespace scatterlab {

class SampleStream {
 public:
  // Pixel and sample indices below MaxStreamIndex (the renderer's limits keep them there).
  static constexpr uint64_t MaxStreamIndex = uint64_t(1) << 32;

  SampleStream(uint64_t seed, uint64_t pixel, uint64_t sample) : rng_(seed, (pixel << 32) | sample) {}

  double next() { return rng_.uniform(); }
  Vec2d next2D() { return rng_.uniform2D(); }

 private:
  CounterRng rng_;
};

}  // namespace scatterlab
