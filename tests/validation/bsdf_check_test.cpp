// The suite as `scatterlab check` runs it, on models whose answers are known.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/smooth_conductor.h"
#include "tests/validation/test_models.h"
#include "validation/bsdf_check.h"
#include "validation/energy.h"

namespace scatterlab {
namespace bsdf_check_test {

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
  // Rows: 6 or 7 checks per angle (furnace for lossless) + reciprocity.
  EXPECT_EQ(r.rows.size(), 3u * 7u + 1u);
}

// The furnace limit of a model exact by construction is the quadrature's own error: far below
// 1e-6 for the cosine lobe (the error estimate of cos/pi over the cells, plus 1e-9 round-off).
TEST(BsdfCheck, ExactModelsFurnaceLimitIsTheQuadraturesOwnError) {
  const CheckReport r = runBsdfChecks(LambertianBsdf(Rgb(1.0)), "white", quickOptions());
  for (const double theta : {0.0, 60.0, 89.9}) {
    const CheckRow* furnace = r.find("furnace", theta);
    ASSERT_NE(furnace, nullptr);
    EXPECT_LT(furnace->threshold, 1e-6) << furnace->note;
    EXPECT_TRUE(furnace->passed) << furnace->note;
  }
}

// A white mirror (a perfect conductor, k = 1e8) reflects 1 - O(1e-16): its furnace row passes
// at the round-off limit, with no quadrature in it (a delta lobe).
TEST(BsdfCheck, PerfectMirrorPassesTheFurnaceToRoundOff) {
  const SmoothConductorBsdf mirror(Rgb(1.0), Rgb(1e8));
  ASSERT_TRUE(mirror.isLossless());
  const CheckReport r = runBsdfChecks(mirror, "perfect-mirror", quickOptions());
  EXPECT_TRUE(r.passed()) << formatTable(r);
  const CheckRow* furnace = r.find("furnace", 60);
  ASSERT_NE(furnace, nullptr);
  EXPECT_LT(furnace->threshold, 3e-9);  // 1e-9 accuracy + 1e-9 round-off + no quadrature
  EXPECT_FALSE(SmoothConductorBsdf(Rgb(1.0), Rgb(1e3)).isLossless());  // F = 1 - 4e-6 at normal incidence
}

// Negative control: a Lambertian of albedo 0.999 that claims to be lossless. Everything about
// its sampling is right, so only the furnace rows may fail, and they must: 0.1% is far beyond
// an exact model's limit.
class LosslessClaimLambertian final : public BsdfModel {
 public:
  explicit LosslessClaimLambertian(double albedo) : lambertian_(Rgb(albedo)) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return lambertian_.eval(wi, wo, mode);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return lambertian_.pdf(wi, wo, mode);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    return lambertian_.sample(wi, uLobe, u, mode);
  }
  LobeFlags flags() const override { return lambertian_.flags(); }
  bool isLossless() const override { return true; }

 private:
  LambertianBsdf lambertian_;
};

TEST(BsdfCheck, LosslessClaimAThousandthShortFailsOnlyTheFurnace) {
  const CheckReport r = runBsdfChecks(LosslessClaimLambertian(0.999), "claims-lossless", quickOptions());
  EXPECT_FALSE(r.passed());
  for (const CheckRow& row : r.rows)
    EXPECT_EQ(row.passed, row.test != "furnace")
        << row.test << " at " << row.wiThetaDeg.value_or(-1) << ": " << row.note;
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
  const CheckReport r = runBsdfChecks(test_models::MirrorPlusDiffuse(0.4), "mirror+diffuse", quickOptions());
  EXPECT_TRUE(r.passed()) << formatTable(r);
}

TEST(BsdfCheck, WrongWeightFailsConsistencyButNotChiSquare) {
  const CheckReport r =
      runBsdfChecks(test_models::WrongWeightLambertian(1.01), "wrong-weight", quickOptions());
  EXPECT_FALSE(r.passed());
  EXPECT_TRUE(r.find("chi2", 60)->passed);
  EXPECT_FALSE(r.find("consistency", 60)->passed);
  EXPECT_FALSE(r.find("albedo-mc", 60)->passed);  // sampled albedo 1% above quadrature
}

// Non-finite weights are counted, sample by sample: the "invalid values" row fails with their
// number (about a quarter of the samples here), where a sound Lambertian's row reads 0.
TEST(BsdfCheck, NonFiniteWeightsAreCountedAndFailTheirRow) {
  BsdfCheckOptions o = quickOptions();
  o.wiThetaDeg = {30};
  const CheckRow* row = nullptr;
  const CheckReport broken = runBsdfChecks(test_models::FaultyWeightLambertian(0.25), "nan", o);
  ASSERT_NE(row = broken.find("invalid values", 30), nullptr);
  EXPECT_FALSE(row->passed);
  EXPECT_NEAR(row->statistic, 0.25 * double(o.samples), 5.0 * std::sqrt(0.25 * 0.75 * double(o.samples)));
  EXPECT_NE(row->note.find("not finite"), std::string::npos) << row->note;
  const CheckReport sound = runBsdfChecks(LambertianBsdf(Rgb(0.5)), "sound", o);
  ASSERT_NE(row = sound.find("invalid values", 30), nullptr);
  EXPECT_TRUE(row->passed);
  EXPECT_EQ(row->statistic, 0.0);
}

// The normalisation row holds the pdf to 1e-5 where the quadrature's own error estimate is
// below that: a white Lambertian (cos / pi, which Simpson's rule integrates exactly) shows an
// estimate below 1e-12, and a pdf 0.1% too large everywhere, which the old limit of 1e-3
// let through, fails.
TEST(BsdfCheck, NormalisationCatchesAPdfOffByOnePermille) {
  BsdfCheckOptions o = quickOptions();
  o.wiThetaDeg = {0, 60, 89.9};
  const CheckReport sound = runBsdfChecks(LambertianBsdf(Rgb(0.5)), "sound", o);
  const CheckReport broken = runBsdfChecks(test_models::ScaledPdfLambertian(1.001), "pdf x 1.001", o);
  for (const double wi : o.wiThetaDeg) {
    const CheckRow* good = sound.find("normalisation", wi);
    ASSERT_NE(good, nullptr);
    EXPECT_TRUE(good->passed) << good->note;
    EXPECT_DOUBLE_EQ(good->threshold, NormalisationTarget);
    EXPECT_LT(good->statistic, 1e-12) << good->note;
    EXPECT_NE(good->note.find("quadrature error estimate"), std::string::npos) << good->note;
    const CheckRow* bad = broken.find("normalisation", wi);
    ASSERT_NE(bad, nullptr);
    EXPECT_FALSE(bad->passed) << bad->note;
    EXPECT_NEAR(bad->statistic, 1e-3, 1e-9) << bad->note;
    EXPECT_TRUE(broken.find("consistency", wi)->passed);  // sample() and pdf() agree: only the scale is off
  }
}

// A delta lobe alone puts every sample into one cell: 0 degrees of freedom, so the chi-square
// row gives no p-value, says so, and tests the count instead.
TEST(BsdfCheck, ADeltaLobeAloneHasNoPValue) {
  BsdfCheckOptions o = quickOptions();
  o.wiThetaDeg = {30};
  const CheckReport r = runBsdfChecks(SmoothConductorBsdf(Rgb(0.2), Rgb(3.9)), "mirror", o);
  const CheckRow* chi = r.find("chi2", 30);
  ASSERT_NE(chi, nullptr);
  EXPECT_TRUE(chi->passed) << chi->note;
  EXPECT_EQ(chi->dof, 0);
  EXPECT_FALSE(chi->pValue.has_value());
  EXPECT_NE(chi->note.find("no degrees of freedom"), std::string::npos) << chi->note;
  EXPECT_NE(formatTable(r).find("no p-value"), std::string::npos);
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
  const CheckReport r = runBsdfChecks(test_models::NonReciprocalDiffuse(), "non-reciprocal", quickOptions());
  EXPECT_FALSE(r.rows.back().passed);
  EXPECT_EQ(r.rows.back().test, "reciprocity");
}

}  // namespace bsdf_check_test
}  // namespace scatterlab
