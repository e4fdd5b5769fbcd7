// The pixel filters draw film offsets with exactly the filter's normalised density: a
// chi-square test over a 2-D histogram of offsets against the box's uniform cells and the
// truncated Gaussian's cell probabilities (products of differences of erf), and a negative
// control with the wrong sigma.
#include <gtest/gtest.h>

#include "integrator/pixel_filter.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace pixel_filter_test {

// 3 tests at family-wise 1%.
const double Threshold = sidakSignificance(0.01, 3);
constexpr int Bins = 24;
constexpr size_t Samples = 400'000;

// Probability that a normal(0, sigma) truncated to [-r, r] falls in [a, b].
double truncatedNormalMass(double a, double b, double sigma, double r) {
  const auto cdf = [&](double x) { return 0.5 * std::erf(x / (sigma * std::sqrt(2.0))); };
  return (cdf(b) - cdf(a)) / (cdf(r) - cdf(-r));
}

Table2D observedOffsets(const PixelFilter& filter, double extent) {
  Table2D counts(Bins, Bins);
  for (size_t i = 0; i < Samples; ++i) {
    SampleStream random(3, i, 0);
    const Vec2d offset = filter.sampleOffset(random);
    EXPECT_LE(std::abs(offset.x), extent);
    EXPECT_LE(std::abs(offset.y), extent);
    const int cx = std::min(int((offset.x + extent) / (2 * extent) * Bins), Bins - 1);
    const int cy = std::min(int((offset.y + extent) / (2 * extent) * Bins), Bins - 1);
    counts(cy, cx) += 1;
  }
  return counts;
}

Table2D expectedGaussian(double sigma, double radius) {
  Table2D expected(Bins, Bins);
  const double width = 2 * radius / Bins;
  for (int cy = 0; cy < Bins; ++cy)
    for (int cx = 0; cx < Bins; ++cx)
      expected(cy, cx) =
          Samples * truncatedNormalMass(-radius + cx * width, -radius + (cx + 1) * width, sigma, radius) *
          truncatedNormalMass(-radius + cy * width, -radius + (cy + 1) * width, sigma, radius);
  return expected;
}

TEST(PixelFilter, BoxIsUniformOverThePixel) {
  const Table2D observed = observedOffsets(PixelFilter::box(), 0.5);
  const Table2D expected(Bins, Bins, double(Samples) / (Bins * Bins));
  const auto r = chiSquareFromTables(observed, expected, Samples, Threshold);
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue;
}

TEST(PixelFilter, GaussianIsTheTruncatedNormal) {
  const PixelFilter filter = PixelFilter::gaussian(0.5, 1.5);
  const auto r =
      chiSquareFromTables(observedOffsets(filter, 1.5), expectedGaussian(0.5, 1.5), Samples, Threshold);
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue;
}

TEST(PixelFilter, GaussianTestRejectsAnotherSigma) {
  const PixelFilter filter = PixelFilter::gaussian(0.5, 1.5);
  const auto r =
      chiSquareFromTables(observedOffsets(filter, 1.5), expectedGaussian(0.52, 1.5), Samples, Threshold);
  EXPECT_FALSE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue;
}

TEST(PixelFilter, RejectsImpossibleParameters) {
  EXPECT_THROW(PixelFilter::gaussian(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(PixelFilter::gaussian(1.0, 0.5), std::invalid_argument);
}

}  // namespace pixel_filter_test
}  // namespace scatterlab
