// The kit's power: every deliberately broken sampler is rejected by the chi-square test,
// while the correct model passes with the same settings. (The conductor's controls, with
// the roughness mismatch, are in tests/materials/bsdf/conductor_kit_test.cpp.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "materials/bsdf/lambertian.h"
#include "tests/test_names.h"
#include "validation/bsdf_check.h"
#include "validation/bsdf_sampling.h"
#include "validation/negative_controls.h"

namespace scatterlab {
namespace negative_controls_test {

ChiSquareOptions options() {
  ChiSquareOptions o;
  o.grid = {64, 128};
  o.sampleCount = 1000000;
  o.seed = 5;
  o.threshold = sidakSignificance(0.01, 8);
  return o;
}

struct ControlCase {
  NegativeControl control;
  double wiTheta;
};
std::string name(const ControlCase& c) {
  // "pdf +5% on half the sphere" at 60 -> "pdf_5_on_half_the_sphere_wi60".
  return test_names::readableTestName(toString(c.control)) + "_wi" + std::to_string(int(c.wiTheta));
}
void PrintTo(const ControlCase& c, std::ostream* os) { *os << toString(c.control) << " at wi " << c.wiTheta; }

std::vector<ControlCase> lambertianControls() {
  std::vector<ControlCase> cases;
  for (const NegativeControl control :
       {NegativeControl::PdfHighOnHalf, NegativeControl::MissingJacobian, NegativeControl::SwappedDirections})
    for (const double wiTheta : {0.0, 60.0, 89.0}) cases.push_back({control, wiTheta});
  return cases;
}

class LambertianControls : public ::testing::TestWithParam<ControlCase> {};

TEST_P(LambertianControls, AreRejected) {
  const auto [control, wiTheta] = GetParam();
  const LambertianBsdf model(Rgb(0.8));
  const Vec3d wi = directionFromDegrees(wiTheta, 30);
  const auto broken = makeNegativeControl(control, model, wi);
  const auto r = bsdfChiSquareTest(*broken, wi, options());
  EXPECT_FALSE(r.passed) << toString(control) << " at wi " << wiTheta << ": chi2 " << r.statistic << " dof "
                         << r.dof << " p " << r.pValue;
}

INSTANTIATE_TEST_SUITE_P(Kit, LambertianControls, ::testing::ValuesIn(lambertianControls()),
                         [](const ::testing::TestParamInfo<ControlCase>& info) { return name(info.param); });

TEST(NegativeControls, CorrectLambertianPassesWithTheSameSettings) {
  const LambertianBsdf model(Rgb(0.8));
  for (double wiTheta : {0.0, 60.0}) {
    const auto r = bsdfChiSquareTest(model, directionFromDegrees(wiTheta, 30), options());
    EXPECT_TRUE(r.passed) << "wi " << wiTheta << ": chi2 " << r.statistic << " dof " << r.dof << " p "
                          << r.pValue;
  }
}

TEST(NegativeControls, NoOpControlIsRecognised) {
  // A sampler "with another roughness" that is the model itself changes nothing.
  const LambertianBsdf model(Rgb(0.8));
  const Vec3d wi = directionFromDegrees(30, 0);
  const auto same = makeNegativeControl(NegativeControl::RoughnessMismatch, model, wi, &model);
  EXPECT_TRUE(negativeControlIsNoOp(NegativeControl::RoughnessMismatch, model, *same, wi));
  const auto swapped = makeNegativeControl(NegativeControl::SwappedDirections, model, wi);
  EXPECT_FALSE(negativeControlIsNoOp(NegativeControl::SwappedDirections, model, *swapped, wi));
}

TEST(NegativeControls, RoughnessMismatchNeedsItsSampler) {
  const LambertianBsdf model(Rgb(0.8));
  EXPECT_THROW(makeNegativeControl(NegativeControl::RoughnessMismatch, model, Vec3d(0, 0, 1)),
               std::invalid_argument);
}

TEST(NegativeControls, SuiteReportsControlsAsRejected) {
  const LambertianBsdf model(Rgb(0.8));
  BsdfCheckOptions o;
  o.wiThetaDeg = {45};
  o.samples = 200000;
  o.thetaBins = 32;
  o.phiBins = 64;
  const CheckReport report = runNegativeControls(model, nullptr, "lambertian", o);
  ASSERT_EQ(report.rows.size(), 4u);  // three controls at one angle + roughness n/a
  for (const CheckRow& row : report.rows) EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
  EXPECT_NE(report.rows.back().note.find("not applicable"), std::string::npos);
}

}  // namespace negative_controls_test
}  // namespace scatterlab
