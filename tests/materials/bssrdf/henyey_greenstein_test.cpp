#include <gtest/gtest.h>

#include "materials/bssrdf/henyey_greenstein.h"
#include "materials/core/quadrature.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace henyey_greenstein_test {

TEST(HenyeyGreenstein, NormalisedWithMeanCosineG) {
  for (const double g : {-0.8, -0.3, 0.0, 0.5, 0.95}) {
    QuadratureOptions q;
    q.relativeTolerance = 1e-12;
    q.minDepth = 8;
    EXPECT_NEAR(2 * Pi * adaptiveSimpson([g](double mu) { return henyeyGreenstein(mu, g); }, -1.0, 1.0, q),
                1.0, 1e-9);
    EXPECT_NEAR(
        2 * Pi * adaptiveSimpson([g](double mu) { return mu * henyeyGreenstein(mu, g); }, -1.0, 1.0, q), g,
        1e-9);
  }
}

TEST(HenyeyGreenstein, CosineSamplerAndCdfRoundTrip) {
  for (const double g : {-0.9, -0.2, 0.0, 1e-9, 0.6, 0.97})
    for (double u = 0.0; u <= 1.0; u += 0.01)
      EXPECT_NEAR(henyeyGreensteinCdf(g, sampleHenyeyGreensteinCos(g, u)), u, 1e-12);
}

// Directions scattered from a tilted propagation direction, through the spherical chi-square
// kit against the phase function (per solid angle).
TEST(HenyeyGreenstein, SampledDirectionsPassTheChiSquareKit) {
  const Vec3d w = glm::normalize(Vec3d(0.3, -0.5, 0.8));
  for (const double g : {-0.4, 0.0, 0.7}) {
    ChiSquareOptions o;
    o.grid = {48, 96};
    o.sampleCount = 300000;
    o.threshold = sidakSignificance(0.01, 3);
    auto draw = [&](CounterRng& rng) -> std::optional<DirectionSample> {
      const Vec3d d = sampleHenyeyGreenstein(w, g, rng.uniform2D());
      return DirectionSample{d, henyeyGreenstein(glm::dot(w, d), g)};
    };
    const ChiSquareResult r = sphericalChiSquareTest(
        draw, [&](const Vec3d& d) { return henyeyGreenstein(glm::dot(w, d), g); }, o);
    EXPECT_TRUE(r.passed) << "g " << g << " chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue
                          << " " << r.failure;
  }
}

}  // namespace henyey_greenstein_test
}  // namespace scatterlab
