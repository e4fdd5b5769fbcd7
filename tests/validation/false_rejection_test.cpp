// The test's size: a correct sampler must be rejected at rate ~alpha over many seeds, and
// its p-values must be uniform. (A test that rarely rejects correct samplers but never
// rejects wrong ones is useless; negative_controls_test.cpp covers the other side.)
#include <gtest/gtest.h>

#include <algorithm>

#include "materials/bsdf/lambertian.h"
#include "validation/bsdf_sampling.h"
#include "validation/energy.h"

namespace scatterlab {
namespace {

TEST(FalseRejection, RateMatchesSignificanceAndPValuesAreUniform) {
  const LambertianBsdf model(Rgb(0.6));
  const Vec3d wi = directionFromDegrees(35, 20);
  const SphericalGrid grid{16, 32};
  const size_t n = 20000;
  // The expected counts depend only on the pdf: integrate once, draw many histograms.
  const std::vector<double> integrals =
      integrateCells(grid, [&](const Vec3d& wo) { return model.pdf(wi, wo, TransportMode::Radiance); }, {}, QuadratureOptions{});
  const int runs = 400;
  const double alpha = 0.05;
  int rejected = 0;
  std::vector<double> pValues;
  for (int seed = 0; seed < runs; ++seed) {
    const SampleHistogram h = drawSamples(grid, bsdfDirectionSampler(model, wi), n, 1000 + seed);
    const ChiSquareResult r = chiSquareFromTables(h.counts, expectedCounts(grid, integrals, {}, n), n, alpha);
    rejected += r.passed ? 0 : 1;
    pValues.push_back(r.pValue);
  }
  // Binomial(400, 0.05): mean 20, sd 4.36; accept within 3.5 sd.
  EXPECT_NEAR(rejected, runs * alpha, 3.5 * std::sqrt(runs * alpha * (1 - alpha))) << rejected << " rejections";
  // Kolmogorov-Smirnov against U(0, 1): D_crit(n = 400, 0.001) = 1.95 / sqrt(400) = 0.0976.
  std::sort(pValues.begin(), pValues.end());
  double d = 0;
  for (int i = 0; i < runs; ++i)
    d = std::max({d, std::abs(pValues[i] - double(i) / runs), std::abs(pValues[i] - double(i + 1) / runs)});
  EXPECT_LT(d, 1.95 / std::sqrt(double(runs))) << "KS distance of p-values from uniform";
}

}  // namespace
}  // namespace scatterlab
