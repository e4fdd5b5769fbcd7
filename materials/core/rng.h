// A counter-based random generator: the k-th number of stream s under seed is a pure function
// of (seed, s, k), so sample i of a test or pixel p of a render draws the same numbers however
// the work is split between threads.
//
// Philox4x32-10 (Salmon et al. 2011, "Parallel random numbers: as easy as 1, 2, 3", SC'11):
// a 10-round bijection of a 128-bit counter under a 64-bit key. Counter = (k, stream),
// key = seed. Passes BigCrush per the paper; used by cuRAND, JAX and Random123.
#pragma once

#include <array>
#include <cstdint>

#include "materials/core/math.h"

namespace scatterlab {

class CounterRng {
 public:
  CounterRng(uint64_t seed, uint64_t stream) : key_(seed), stream_(stream) {}

  // Uniform double in [0, 1) with 53 random bits.
  double uniform() {
    if (cached_ == 0) refill();
    const uint64_t bits = (uint64_t(block_[4 - cached_]) << 32) | block_[5 - cached_];
    cached_ -= 2;
    return double(bits >> 11) * 0x1.0p-53;
  }
  Vec2d uniform2D() {
    const double a = uniform();
    return {a, uniform()};
  }

  // The raw 128-bit output block for counter value k (exposed for tests against the
  // published known-answer vectors).
  static std::array<uint32_t, 4> philox(std::array<uint32_t, 4> counter, std::array<uint32_t, 2> key) {
    constexpr uint32_t M0 = 0xD2511F53u, M1 = 0xCD9E8D57u;
    constexpr uint32_t W0 = 0x9E3779B9u, W1 = 0xBB67AE85u;
    for (int round = 0; round < 10; ++round) {
      const uint64_t p0 = uint64_t(M0) * counter[0];
      const uint64_t p1 = uint64_t(M1) * counter[2];
      counter = {uint32_t(p1 >> 32) ^ counter[1] ^ key[0], uint32_t(p1),
                 uint32_t(p0 >> 32) ^ counter[3] ^ key[1], uint32_t(p0)};
      key[0] += W0;
      key[1] += W1;
    }
    return counter;
  }

 private:
  void refill() {
    block_ =
        philox({uint32_t(counter_), uint32_t(counter_ >> 32), uint32_t(stream_), uint32_t(stream_ >> 32)},
               {uint32_t(key_), uint32_t(key_ >> 32)});
    ++counter_;
    cached_ = 4;
  }

  uint64_t key_, stream_;
  uint64_t counter_ = 0;
  std::array<uint32_t, 4> block_{};
  int cached_ = 0;  // 32-bit words of block_ not yet used (consumed two at a time)
};

// Independent seeds for sub-tasks of one seeded job (say, one per incident angle):
// SplitMix64's finaliser (Steele et al. 2014) of seed and task index.
inline uint64_t deriveSeed(uint64_t seed, uint64_t task) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull * (task + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace scatterlab
