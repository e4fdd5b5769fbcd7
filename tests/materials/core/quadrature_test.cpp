// Adaptive Simpson against closed forms, including the case it exists for: a lobe far
// narrower than the first grid of points.
#include <gtest/gtest.h>

#include "materials/core/math.h"
#include "materials/core/quadrature.h"

namespace scatterlab {
namespace quadrature_test {

TEST(AdaptiveSimpson, ExactForCubics) {
  // Simpson's rule integrates cubics exactly: int_0^2 x^3 - x dx = 4 - 2.
  EXPECT_NEAR(adaptiveSimpson([](double x) { return x * x * x - x; }, 0.0, 2.0), 2.0, 1e-14);
}

TEST(AdaptiveSimpson, SmoothFunctionToRelativeTolerance) {
  const double exact = std::exp(3.0) - 1.0;
  EXPECT_NEAR(adaptiveSimpson([](double x) { return std::exp(x); }, 0.0, 3.0), exact, 1e-6 * exact);
}

TEST(AdaptiveSimpson, FindsNarrowPeakAtAnEndpoint) {
  // A GGX alpha = 0.001 lobe at normal incidence is ~1e-6 wide in cos(theta) and sits at the
  // end of its cell. int_0^1 exp(-(1 - x) / w) / w dx = 1 - exp(-1 / w).
  const double w = 1e-6;
  const double got = adaptiveSimpson([w](double x) { return std::exp(-(1.0 - x) / w) / w; }, 0.0, 1.0);
  EXPECT_NEAR(got, 1.0, 1e-6);
}

TEST(AdaptiveSimpson, VectorValuesIntegrateComponentwise) {
  const glm::dvec4 got =
      adaptiveSimpson([](double x) { return glm::dvec4(1.0, x, x * x, std::sin(x)); }, 0.0, Pi);
  EXPECT_NEAR(got.x, Pi, 1e-12);
  EXPECT_NEAR(got.y, Pi * Pi / 2, 1e-12);
  EXPECT_NEAR(got.z, Pi * Pi * Pi / 3, 1e-10);
  EXPECT_NEAR(got.w, 2.0, 1e-6 * 2.0);
}

TEST(AdaptiveSimpson, TwoDimensionalGaussian) {
  // int over [-4,4]^2 of exp(-(x^2 + y^2)) = pi erf(4)^2.
  const double got =
      adaptiveSimpson2D([](double x, double y) { return std::exp(-(x * x + y * y)); }, -4, 4, -4, 4);
  EXPECT_NEAR(got, Pi * sqr(std::erf(4.0)), 1e-6 * Pi);
}

TEST(AdaptiveSimpson, JumpIsResolvedByDepth) {
  // A step at an irrational point: the integral converges to its exact value as depth allows.
  const double jump = 1.0 / std::sqrt(2.0);
  const double got = adaptiveSimpson([=](double x) { return x < jump ? 1.0 : 0.0; }, 0.0, 1.0);
  EXPECT_NEAR(got, jump, 1e-6);
}

}  // namespace quadrature_test
}  // namespace scatterlab
