#include <gtest/gtest.h>

#include "materials/core/rng.h"

namespace scatterlab {
namespace rng_test {

// Known-answer vectors of Philox4x32-10 from Random123's kat_vectors (Salmon et al. 2011).
TEST(CounterRng, PhiloxKnownAnswers) {
  using A4 = std::array<uint32_t, 4>;
  EXPECT_EQ(CounterRng::philox({0, 0, 0, 0}, {0, 0}),
            (A4{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
  EXPECT_EQ(
      CounterRng::philox({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}, {0xffffffffu, 0xffffffffu}),
      (A4{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
  EXPECT_EQ(
      CounterRng::philox({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, {0xa4093822u, 0x299f31d0u}),
      (A4{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}));
}

TEST(CounterRng, SameSeedAndStreamGiveSameSequence) {
  CounterRng a(42, 7), b(42, 7);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.uniform(), b.uniform());
}

TEST(CounterRng, StreamsAndSeedsDiffer) {
  CounterRng a(42, 7), b(42, 8), c(43, 7);
  int sameB = 0, sameC = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform();
    sameB += x == b.uniform();
    sameC += x == c.uniform();
  }
  EXPECT_EQ(sameB, 0);
  EXPECT_EQ(sameC, 0);
}

TEST(CounterRng, UniformIsInUnitIntervalWithCorrectMoments) {
  // Mean 1/2 and variance 1/12; with n = 1e6 the standard errors are 2.9e-4 and 8.3e-5.
  CounterRng rng(1, 0);
  const int n = 1000000;
  double sum = 0, sumSq = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sumSq += u * u;
  }
  const double mean = sum / n, variance = sumSq / n - mean * mean;
  EXPECT_NEAR(mean, 0.5, 5 * 2.9e-4);
  EXPECT_NEAR(variance, 1.0 / 12.0, 5 * 8.3e-5);
}

TEST(CounterRng, DerivedSeedsAreDistinct) {
  EXPECT_NE(deriveSeed(1, 0), deriveSeed(1, 1));
  EXPECT_NE(deriveSeed(1, 0), deriveSeed(2, 0));
  EXPECT_EQ(deriveSeed(5, 3), deriveSeed(5, 3));
}

}  // namespace rng_test
}  // namespace scatterlab
