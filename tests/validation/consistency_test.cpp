#include <gtest/gtest.h>

#include "tests/validation/test_models.h"
#include "validation/consistency.h"
#include "validation/reciprocity.h"

namespace scatterlab {
namespace consistency_test {

const SphericalGrid Grid{16, 32};

TEST(Consistency, LambertianIsConsistentAndItsMonteCarloAlbedoIsExact) {
  const LambertianBsdf model(Rgb(0.2, 0.5, 0.9));
  const ConsistencyResult r = checkConsistency(model, directionFromDegrees(30, 0), Grid, 50000, 3, 20000);
  EXPECT_TRUE(r.passed()) << r.firstFailure;
  EXPECT_LT(r.maxWeightError, 1e-12);
  // Every weight equals the albedo, so the mean is exact and its standard error 0.
  EXPECT_NEAR(r.albedoMean.x, 0.2, 1e-12);
  EXPECT_NEAR(r.albedoMean.z, 0.9, 1e-12);
}

TEST(Consistency, WeightOffByOnePercentFails) {
  const test_models::WrongWeightLambertian model(1.01);
  const ConsistencyResult r = checkConsistency(model, directionFromDegrees(30, 0), Grid, 20000, 3, 1000);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(r.inconsistentSamples, r.samples);
  EXPECT_NEAR(r.maxWeightError, 0.01 / 1.01, 1e-9);
  EXPECT_NE(r.firstFailure.find("weight"), std::string::npos) << r.firstFailure;
}

TEST(Consistency, ReflectanceWhereThePdfIsZeroIsFound) {
  // Half of the hemisphere (wo.y < 0) is reflected but never sampled: about 1/4 of uniform
  // sphere probes land there.
  const test_models::HalfSupportSampler model;
  const ConsistencyResult r = checkConsistency(model, directionFromDegrees(30, 0), Grid, 20000, 3, 40000);
  EXPECT_FALSE(r.passed());
  EXPECT_NEAR(double(r.supportViolations) / 40000, 0.25, 0.01);
}

TEST(Reciprocity, LambertianIsReciprocal) {
  const ReciprocityResult r = checkReciprocity(LambertianBsdf(Rgb(0.7)), 20000, 5);
  EXPECT_TRUE(r.passed()) << r.worst;
  EXPECT_EQ(r.maxError, 0.0);
}

TEST(Reciprocity, NonReciprocalModelIsCaught) {
  const ReciprocityResult r = checkReciprocity(test_models::NonReciprocalDiffuse(), 20000, 5);
  EXPECT_FALSE(r.passed());
  EXPECT_GT(r.violations, 1000u);
  EXPECT_FALSE(r.worst.empty());
}

}  // namespace consistency_test
}  // namespace scatterlab
