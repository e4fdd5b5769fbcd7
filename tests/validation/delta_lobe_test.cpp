// Delta lobes in the chi-square test (Mitsuba 0.6's method): discrete directions add
// N * P(lobe) to their cell's expectation, so the lobe's selection probability is tested too.
#include <gtest/gtest.h>

#include "tests/validation/test_models.h"
#include "validation/bsdf_sampling.h"

namespace scatterlab {
namespace delta_lobe_test {

ChiSquareOptions options() {
  ChiSquareOptions o;
  o.grid = {32, 64};
  o.sampleCount = 400000;
  o.seed = 11;
  o.threshold = sidakSignificance(0.01, 3);
  return o;
}

TEST(DeltaLobe, CorrectMixtureOfMirrorAndDiffusePasses) {
  const test_models::MirrorPlusDiffuse model(0.3);
  const auto r = bsdfChiSquareTest(model, directionFromDegrees(40, 30), options());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(DeltaLobe, WrongDiscreteProbabilityIsRejected) {
  // The sampler picks the mirror 30% of the time but claims 27%.
  const test_models::MirrorPlusDiffuse model(0.3, 0.27);
  const auto r = bsdfChiSquareTest(model, directionFromDegrees(40, 30), options());
  EXPECT_FALSE(r.passed);
}

TEST(DeltaLobe, PureDeltaWithCorrectProbabilityPasses) {
  // All samples in one cell: 0 degrees of freedom; the count itself is checked.
  const test_models::MirrorPlusDiffuse model(1.0);
  const auto r = bsdfChiSquareTest(model, directionFromDegrees(60, 10), options());
  EXPECT_TRUE(r.passed) << r.failure;
  EXPECT_EQ(r.dof, 0);
}

}  // namespace delta_lobe_test
}  // namespace scatterlab
