// The 1-D radius chi-square kit on a distribution known in closed form: the exponential, sampled
// by inversion.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/radial_chi_square.h"

namespace scatterlab {
namespace radial_chi_square_test {

const double Threshold = sidakSignificance(0.01, 3);

ChiSquareResult exponentialTest(double sampledRate, double claimedRate, int bins = 40) {
  RadialChiSquareOptions o;
  o.sampleCount = 200000;
  o.seed = 9;
  o.threshold = Threshold;
  const auto quantile = [claimedRate](double u) { return -std::log1p(-u) / claimedRate; };
  return radialChiSquareTest(
      [sampledRate](CounterRng& rng) -> std::optional<double> {
        return -std::log1p(-rng.uniform()) / sampledRate;
      },
      [claimedRate](double r) { return claimedRate * std::exp(-claimedRate * r); },
      equalProbabilityEdges(quantile, bins), quantile(1 - 1e-12), o);
}

TEST(RadialChiSquare, AcceptsACorrectSampler) {
  const ChiSquareResult r = exponentialTest(2.0, 2.0);
  EXPECT_TRUE(r.passed) << r.statistic << " " << r.dof << " " << r.pValue << " " << r.failure;
  EXPECT_EQ(r.dof, 39);
}

TEST(RadialChiSquare, RejectsARateTwoPercentOff) { EXPECT_FALSE(exponentialTest(2.04, 2.0).passed); }

TEST(RadialChiSquare, RejectsInvalidRadii) {
  RadialChiSquareOptions o;
  o.sampleCount = 1000;
  const ChiSquareResult r =
      radialChiSquareTest([](CounterRng&) -> std::optional<double> { return -1.0; },
                          [](double r) { return std::exp(-r); }, {0.0, 1.0, INFINITY}, 40.0, o);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failure.find("invalid"), std::string::npos) << r.failure;
}

TEST(RadialChiSquare, DensityIntegralsSpanManyDecades) {
  // A density with a 1/r^2 tail (CDF r / (1 + r)): its 1 - 1e-12 quantile is 1e12, and the
  // integral along its octiles keeps the whole range, 1e-14 r_1/8 .. 1e12.
  const auto pdf = [](double r) { return 1.0 / ((1.0 + r) * (1.0 + r)); };
  EXPECT_NEAR(integrateAlongQuantiles(pdf, [](double u) { return u / (1.0 - u); }), 1.0, 1e-9);
  EXPECT_NEAR(integrateRadialDensity(pdf, 1.0, 3.0, 0.0), 0.25, 1e-9);  // relative 1e-9 quadrature
  // One interval from 0 starts at 1e-14 of its end: at the distribution's scale, not 1e12 away.
  EXPECT_NEAR(integrateRadialDensity(pdf, 0.0, 1.0, 0.0), 0.5, 1e-9);
}

}  // namespace radial_chi_square_test
}  // namespace scatterlab
