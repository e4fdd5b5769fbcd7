#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/core/monotone_cubic_cdf.h"

namespace scatterlab {
namespace monotone_cubic_cdf_test {

// The CDF of the exponential distribution at nodes: F = 1 - e^-x, f = e^-x.
MonotoneCubicCdf exponentialCdf(int nodes, double last) {
  std::vector<double> x, F, f;
  for (int k = 0; k < nodes; ++k) {
    const double xk = last * k / (nodes - 1);
    x.push_back(xk);
    F.push_back(1.0 - std::exp(-xk));
    f.push_back(std::exp(-xk));
  }
  return MonotoneCubicCdf(x, F, f);
}

TEST(MonotoneCubicCdf, ReproducesTheNodesAndApproximatesASmoothCdf) {
  const MonotoneCubicCdf cdf = exponentialCdf(41, 10.0);
  for (int k = 0; k <= 40; ++k) {
    const double x = 10.0 * k / 40;
    EXPECT_NEAR(cdf.cumulative(x), 1.0 - std::exp(-x), 1e-15);
    EXPECT_NEAR(cdf.density(x), std::exp(-x), 1e-12);
  }
  // Between nodes the cubic Hermite error is O(h^4 F'''' / 384): h = 0.25 gives ~1e-5.
  for (double x = 0.01; x < 10.0; x += 0.173) EXPECT_NEAR(cdf.cumulative(x), 1.0 - std::exp(-x), 2e-5) << x;
  EXPECT_DOUBLE_EQ(cdf.cumulative(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(cdf.cumulative(11.0), 1.0 - std::exp(-10.0));
  EXPECT_EQ(cdf.density(11.0), 0.0);
}

TEST(MonotoneCubicCdf, DensityIsTheDerivativeOfTheCumulative) {
  const MonotoneCubicCdf cdf = exponentialCdf(9, 6.0);
  for (double x = 0.05; x < 6.0; x += 0.31) {
    const double h = 1e-6;
    EXPECT_NEAR((cdf.cumulative(x + h) - cdf.cumulative(x - h)) / (2 * h), cdf.density(x), 1e-8) << x;
  }
}

TEST(MonotoneCubicCdf, StaysMonotoneWhereTheGivenDensitiesWouldOvershoot) {
  // A steep drop over one interval: densities 1000x the secant would make a plain Hermite cubic
  // overshoot and its density negative; the limited one never is.
  const MonotoneCubicCdf cdf({0.0, 1.0, 2.0, 3.0}, {0.0, 0.9, 0.9001, 1.0}, {50.0, 50.0, 0.0, 30.0});
  double previous = -1.0;
  for (double x = 0.0; x <= 3.0; x += 1e-3) {
    const double F = cdf.cumulative(x);
    EXPECT_GE(F, previous) << x;
    EXPECT_GE(cdf.density(x), 0.0) << x;
    previous = F;
  }
}

TEST(MonotoneCubicCdf, InvertRoundTrips) {
  const MonotoneCubicCdf cdf = exponentialCdf(17, 12.0);
  for (double u = 0.0; u < 1.0; u += 0.0137) {
    const double target = u * cdf.total();
    EXPECT_NEAR(cdf.cumulative(cdf.invert(target)), target, 1e-14) << u;
  }
  for (double x = 0.0; x < 12.0; x += 0.29) EXPECT_NEAR(cdf.invert(cdf.cumulative(x)), x, 1e-9) << x;
}

TEST(MonotoneCubicCdf, RejectsDecreasingValuesAndNegativeDensities) {
  EXPECT_THROW(MonotoneCubicCdf({0.0, 1.0}, {0.5, 0.4}, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(MonotoneCubicCdf({0.0, 1.0}, {0.0, 1.0}, {-1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(MonotoneCubicCdf({0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(MonotoneCubicCdf({0.0}, {0.0}, {1.0}), std::invalid_argument);
}

}  // namespace monotone_cubic_cdf_test
}  // namespace scatterlab
