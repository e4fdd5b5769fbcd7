// The kit as a library call (validation/check_bsdf.h), its GoogleTest assertions
// (validation/gtest_check.h) and the adapter around a user's own functions
// (materials/bsdf/function_bsdf.h), on a glossy Phong lobe whose sampling is known to be right.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "materials/bsdf/function_bsdf.h"
#include "materials/bsdf/phong.h"
#include "validation/check_bsdf.h"
#include "validation/gtest_check.h"

namespace scatterlab {
namespace check_bsdf_test {

constexpr double Exponent = 30.0;
const Rgb Ks(0.8);

// A few seconds for every run below; still enough samples to reject a pdf whose exponent is
// 10% off (the chi-square statistic grows with the sample count, PhongBrokenPdf below).
CheckBsdfOptions quickOptions(const std::string& label) {
  CheckBsdfOptions o;
  o.kit.wiThetaDeg = {0, 60};
  o.kit.samples = 200000;
  o.kit.thetaBins = 32;
  o.kit.phiBins = 64;
  o.kit.reciprocityPairs = 5000;
  o.label = label;
  return o;
}

// The Phong lobe as a renderer's three functions would give it.
Rgb phongEvalFunction(const Vec3d& wi, const Vec3d& wo) { return phongEval(Rgb(0.0), Ks, Exponent, wi, wo); }
double phongPdfFunction(const Vec3d& wi, const Vec3d& wo) {
  return wi.z > 0 && wo.z > 0 ? PhongLobe::pdf(Exponent, wi, wo) : 0.0;
}
std::optional<Vec3d> phongSampleFunction(const Vec3d& wi, const Vec2d& u) {
  if (!(wi.z > 0)) return std::nullopt;
  return PhongLobe::sample(Exponent, wi, u);
}

TEST(CheckBsdf, GivesTheRowsOfTheKit) {
  const PhongBsdf phong(Rgb(0.0), Ks, Exponent);
  const CheckBsdfOptions options = quickOptions("phong");
  const CheckReport report = checkBsdf(phong, options);
  const CheckReport kit = runBsdfChecks(phong, "phong", options.kit);
  ASSERT_EQ(report.rows.size(), kit.rows.size());
  for (size_t i = 0; i < kit.rows.size(); ++i) {
    EXPECT_EQ(report.rows[i].test, kit.rows[i].test);
    EXPECT_EQ(report.rows[i].statistic, kit.rows[i].statistic);  // same seeds: the same numbers
  }
  EXPECT_TRUE(report.passed()) << formatVerdict(report);
  const std::string verdict = formatVerdict(report);
  EXPECT_TRUE(verdict.ends_with("\nverdict: PASS\n")) << verdict;
}

TEST(CheckBsdf, NegativeControlsAreRejectedWithTheMismatchedSamplerGiven) {
  const PhongBsdf phong(Rgb(0.0), Ks, Exponent);
  const PhongBsdf mismatched(Rgb(0.0), Ks, Exponent / 1.1);
  CheckBsdfOptions options = quickOptions("phong");
  options.negativeControls = true;
  options.roughnessMismatchSampler = &mismatched;
  const CheckReport report = checkBsdf(phong, options);
  EXPECT_TRUE(report.passed()) << formatVerdict(report);
  const CheckRow* mismatch = report.find("control: sampler lobe width 10% off", 60);
  ASSERT_NE(mismatch, nullptr);
  EXPECT_TRUE(mismatch->pValue && *mismatch->pValue < mismatch->threshold) << mismatch->note;
}

TEST(CheckBsdf, WritesImagesOnRequestIntoADirectoryItCreates) {
  CheckBsdfOptions options = quickOptions("phong");
  options.kit.wiThetaDeg = {30};
  options.kit.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "check-bsdf-images" / "nested";
  std::filesystem::remove_all(options.kit.imageDir->parent_path());
  checkBsdf(PhongBsdf(Rgb(0.0), Ks, Exponent), options);
  for (const char* kind : {"observed", "expected", "residual"})
    EXPECT_TRUE(std::filesystem::exists(*options.kit.imageDir / (std::string("phong_wi30_") + kind + ".png")))
        << kind;
}

TEST(FunctionBsdf, AUsersThreeFunctionsPassTheKit) {
  const FunctionBsdf model(phongEvalFunction, phongPdfFunction, phongSampleFunction,
                           {.flags = LobeFlags::GlossyReflection});
  EXPECT_TRUE(passesBsdfCheck(model, quickOptions("function phong")));
}

TEST(FunctionBsdf, AnEvalWithTheCosineIsConvertedWhenSaidSo) {
  const auto evalWithCosine = [](const Vec3d& wi, const Vec3d& wo) {
    return phongEvalFunction(wi, wo) * std::abs(wo.z);
  };
  const FunctionBsdf converted(evalWithCosine, phongPdfFunction, phongSampleFunction,
                               {.flags = LobeFlags::GlossyReflection, .evalIncludesCosine = true});
  const Vec3d wi(0.5, 0.0, 0.8660254037844386), wo(-0.48, 0.1, 0.8717797887081347);
  EXPECT_NEAR(converted.eval(wi, wo).x, phongEvalFunction(wi, wo).x, 1e-12 * phongEvalFunction(wi, wo).x);
  EXPECT_TRUE(passesBsdfCheck(converted, quickOptions("function phong, cosine in eval")));
  // Left unconverted, f |cos wo| is not reciprocal, which the reciprocity row catches (the
  // weights, computed from the same eval, stay consistent with it).
  const FunctionBsdf unconverted(evalWithCosine, phongPdfFunction, phongSampleFunction,
                                 {.flags = LobeFlags::GlossyReflection});
  const CheckReport report = checkBsdf(unconverted, quickOptions("cosine left in eval"));
  const auto reciprocity = std::find_if(report.rows.begin(), report.rows.end(),
                                        [](const CheckRow& row) { return row.test == "reciprocity"; });
  ASSERT_NE(reciprocity, report.rows.end());
  EXPECT_FALSE(reciprocity->passed) << formatVerdict(report);
}

TEST(FunctionBsdf, AUsersOwnSampleWeightIsCheckedAgainstEvalAndPdf) {
  const auto sampleWithWeight = [](double weightScale) {
    return [weightScale](const Vec3d& wi, double, const Vec2d& u) -> std::optional<BsdfSample> {
      const std::optional<Vec3d> wo = phongSampleFunction(wi, u);
      if (!wo || !(wo->z > 0)) return std::nullopt;
      const double pdf = phongPdfFunction(wi, *wo);
      return BsdfSample{*wo, phongEvalFunction(wi, *wo) * (wo->z / pdf) * weightScale, pdf,
                        LobeFlags::GlossyReflection, 1.0};
    };
  };
  const FunctionBsdf right(phongEvalFunction, phongPdfFunction, sampleWithWeight(1.0),
                           {.flags = LobeFlags::GlossyReflection});
  EXPECT_TRUE(passesBsdfCheck(right, quickOptions("own weights")));
  // Weights 2% high: the per-sample consistency row catches it.
  const FunctionBsdf wrong(phongEvalFunction, phongPdfFunction, sampleWithWeight(1.02),
                           {.flags = LobeFlags::GlossyReflection});
  const CheckReport report = checkBsdf(wrong, quickOptions("own weights 2% high"));
  EXPECT_FALSE(report.find("consistency", 60)->passed) << formatVerdict(report);
}

TEST(FunctionBsdf, APdfWithItsExponent10PercentOffFailsTheKit) {
  const auto brokenPdf = [](const Vec3d& wi, const Vec3d& wo) {
    return wi.z > 0 && wo.z > 0 ? PhongLobe::pdf(Exponent * 1.1, wi, wo) : 0.0;
  };
  // Weights from the broken pdf are self-consistent: only the chi-square test can tell.
  const FunctionBsdf broken(phongEvalFunction, brokenPdf, phongSampleFunction,
                            {.flags = LobeFlags::GlossyReflection});
  EXPECT_TRUE(failsBsdfCheck(broken, quickOptions("pdf exponent 10% off")));
  const CheckReport report = checkBsdf(broken, quickOptions("pdf exponent 10% off"));
  EXPECT_FALSE(report.find("chi2", 0)->passed);
  EXPECT_TRUE(report.find("consistency", 0)->passed);
}

TEST(GtestCheck, AFailureMessageIsTheVerdictTable) {
  const auto brokenPdf = [](const Vec3d& wi, const Vec3d& wo) {
    return wi.z > 0 && wo.z > 0 ? PhongLobe::pdf(Exponent * 1.1, wi, wo) : 0.0;
  };
  const FunctionBsdf broken(phongEvalFunction, brokenPdf, phongSampleFunction,
                            {.flags = LobeFlags::GlossyReflection});
  const ::testing::AssertionResult result = passesBsdfCheck(broken, quickOptions("broken"));
  EXPECT_FALSE(result);
  const std::string message = result.message();
  EXPECT_NE(message.find("the kit rejects broken"), std::string::npos) << message;
  EXPECT_NE(message.find("verdict: FAIL"), std::string::npos) << message;
}

}  // namespace check_bsdf_test
}  // namespace scatterlab
