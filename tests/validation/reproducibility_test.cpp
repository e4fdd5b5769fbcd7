// Same seed, same numbers, for any thread count (docs/design.md, "Seeds and determinism").
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "materials/bsdf/lambertian.h"
#include "validation/bsdf_check.h"
#include "validation/bsdf_sampling.h"
#include "validation/consistency.h"
#include "validation/negative_controls.h"

namespace scatterlab {
namespace reproducibility_test {

template <typename F> auto withThreads(int threads, const F& f) {
  tbb::task_arena arena(threads);
  return arena.execute(f);
}

TEST(Reproducibility, ChiSquareTablesDoNotDependOnThreadCount) {
  const LambertianBsdf model(Rgb(0.5));
  ChiSquareOptions o;
  o.grid = {16, 32};
  o.sampleCount = 100000;
  const Vec3d wi = directionFromDegrees(45, 0);
  const auto one = withThreads(1, [&] { return bsdfChiSquareTest(model, wi, o); });
  const auto two = withThreads(2, [&] { return bsdfChiSquareTest(model, wi, o); });
  const auto four = withThreads(4, [&] { return bsdfChiSquareTest(model, wi, o); });
  EXPECT_EQ(one.observed.values, two.observed.values);
  EXPECT_EQ(one.expected.values, two.expected.values);
  EXPECT_EQ(one.observed.values, four.observed.values);
  EXPECT_EQ(one.statistic, four.statistic);
}

TEST(Reproducibility, MonteCarloAlbedoDoesNotDependOnThreadCount) {
  // Floating-point sums depend on their order only when the terms differ (a Lambertian's
  // constant weights would hide a non-deterministic reduction): the pdf-high control gives
  // half of the samples a weight 1/1.05 times the other half's.
  const LambertianBsdf base(Rgb(0.5));
  const Vec3d wi = directionFromDegrees(45, 0);
  const auto model = makeNegativeControl(NegativeControl::PdfHighOnHalf, base, wi);
  const SphericalGrid grid{16, 32};
  const auto one = withThreads(1, [&] { return checkConsistency(*model, wi, grid, 100000, 9, 1000); });
  const auto two = withThreads(2, [&] { return checkConsistency(*model, wi, grid, 100000, 9, 1000); });
  EXPECT_EQ(one.albedoMean, two.albedoMean);
  EXPECT_EQ(one.maxErrorPerCell.values, two.maxErrorPerCell.values);
}

TEST(Reproducibility, DifferentSeedsGiveDifferentHistograms) {
  const LambertianBsdf model(Rgb(0.5));
  ChiSquareOptions a, b;
  a.grid = b.grid = {16, 32};
  a.sampleCount = b.sampleCount = 20000;
  b.seed = a.seed + 1;
  const Vec3d wi = directionFromDegrees(10, 0);
  EXPECT_NE(bsdfChiSquareTest(model, wi, a).observed.values, bsdfChiSquareTest(model, wi, b).observed.values);
}

}  // namespace reproducibility_test
}  // namespace scatterlab
