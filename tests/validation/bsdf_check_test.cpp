// The suite as `scatterlab check` runs it, on models whose answers are known.
#include <gtest/gtest.h>

#include "materials/bsdf/lambertian.h"
#include "tests/validation/test_models.h"
#include "validation/bsdf_check.h"

namespace scatterlab {
namespace {

BsdfCheckOptions quickOptions() {
  BsdfCheckOptions o;
  o.wiThetaDeg = {0, 60, 89.9};
  o.samples = 200000;
  o.thetaBins = 32;
  o.phiBins = 64;
  o.reciprocityPairs = 5000;
  return o;
}

TEST(BsdfCheck, WhiteLambertianPassesEverythingIncludingFurnace) {
  const CheckReport r = runBsdfChecks(LambertianBsdf(Rgb(1.0)), "white", quickOptions());
  EXPECT_TRUE(r.passed()) << formatTable(r);
  const CheckRow* furnace = r.find("furnace", 60);
  ASSERT_NE(furnace, nullptr);
  EXPECT_LT(furnace->statistic, 1e-5);  // quadrature of cos/pi over the hemisphere
  // Rows: 5 or 6 checks per angle (furnace for lossless) + reciprocity.
  EXPECT_EQ(r.rows.size(), 3u * 6u + 1u);
}

TEST(BsdfCheck, ColouredLambertianAlbedoIsItsAlbedo) {
  const CheckReport r = runBsdfChecks(LambertianBsdf(Rgb(0.25, 0.5, 0.75)), "coloured", quickOptions());
  EXPECT_TRUE(r.passed()) << formatTable(r);
  const CheckRow* albedo = r.find("albedo", 0);
  ASSERT_NE(albedo, nullptr);
  EXPECT_NEAR(albedo->statistic, 0.75, 1e-5);
  EXPECT_EQ(r.find("furnace", 0), nullptr);
}

TEST(BsdfCheck, MirrorPlusDiffuseMixturePassesWithDeltaLobe) {
  const CheckReport r = runBsdfChecks(testing::MirrorPlusDiffuse(0.4), "mirror+diffuse", quickOptions());
  EXPECT_TRUE(r.passed()) << formatTable(r);
}

TEST(BsdfCheck, WrongWeightFailsConsistencyButNotChiSquare) {
  const CheckReport r = runBsdfChecks(testing::WrongWeightLambertian(1.01), "wrong-weight", quickOptions());
  EXPECT_FALSE(r.passed());
  EXPECT_TRUE(r.find("chi2", 60)->passed);
  EXPECT_FALSE(r.find("consistency", 60)->passed);
  EXPECT_FALSE(r.find("albedo-mc", 60)->passed);  // sampled albedo 1% above quadrature
}

TEST(BsdfCheck, ImagesAreWrittenOnRequest) {
  BsdfCheckOptions o = quickOptions();
  o.wiThetaDeg = {30};
  o.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "check-images";
  std::filesystem::remove_all(*o.imageDir);
  runBsdfChecks(LambertianBsdf(Rgb(0.5)), "lambertian", o);
  for (const char* kind : {"observed", "expected", "residual", "consistency"})
    EXPECT_TRUE(std::filesystem::exists(*o.imageDir / (std::string("lambertian_wi30_") + kind + ".png")))
        << kind;
  EXPECT_TRUE(std::filesystem::exists(*o.imageDir / "lambertian_wi30_tables.json"));
}

TEST(BsdfCheck, NonReciprocalModelFailsReciprocityRow) {
  const CheckReport r = runBsdfChecks(testing::NonReciprocalDiffuse(), "non-reciprocal", quickOptions());
  EXPECT_FALSE(r.rows.back().passed);
  EXPECT_EQ(r.rows.back().test, "reciprocity");
}

}  // namespace
}  // namespace scatterlab
