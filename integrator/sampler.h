// The random numbers of one camera sample: a pure function of (seed, pixel, sample index), so
// an image is the same whatever the number of threads and however the tiles are scheduled.
// The project's counter-based generator (materials/core/rng.h, Philox4x32-10) is keyed by the
// seed; its 128-bit counter is (k, stream, pixel, sample) for the k-th block of the sample.
// `stream` keeps the numbers of one sample's independent parts apart: its camera path (0, the
// path tracer's), a light path started for it (light tracing, BDPT), a photon (SPPM).
//
// Each 32-bit word of a block is one uniform number, k / 2^32 in [0, 1): four per Philox call
// where CounterRng::uniform() spends two on 53 bits. A path vertex draws about seven numbers,
// so this halves the generator's share of a render (bench/render_bench.cpp: ~10%). 32 bits is
// more resolution than pbrt-v4's float samples (24 bits) and ample for every warp, the pixel
// filter and the environment map's two-level table (1024 columns leave 22 bits within a cell).
#pragma once

#include <array>
#include <cstdint>

#include "materials/core/rng.h"

namespace scatterlab {

enum class StreamPart : uint32_t { Camera = 0, LightPath = 1, Photon = 2 };

class SampleStream {
 public:
  // Pixel and sample indices below MaxStreamIndex (the renderer's limits keep them there).
  static constexpr uint64_t MaxStreamIndex = uint64_t(1) << 32;

  SampleStream(uint64_t seed, uint64_t pixel, uint64_t sample, StreamPart part = StreamPart::Camera)
      : key_{uint32_t(seed), uint32_t(seed >> 32)},
        part_(uint32_t(part)),
        pixel_(uint32_t(pixel)),
        sample_(uint32_t(sample)) {}

  double next() {
    if (cached_ == 0) refill();
    return double(block_[4 - cached_--]) * 0x1.0p-32;
  }
  Vec2d next2D() {
    const double a = next();
    return {a, next()};
  }

 private:
  void refill() {
    block_ = CounterRng::philox({counter_++, part_, pixel_, sample_}, key_);
    cached_ = 4;
  }

  std::array<uint32_t, 2> key_;
  uint32_t part_, pixel_, sample_;
  uint32_t counter_ = 0;
  std::array<uint32_t, 4> block_{};
  int cached_ = 0;
};

}  // namespace scatterlab
