// Normalised Phong and Ngan's Blinn-Phong: values at fixed directions computed by hand from
// the papers' formulas, reciprocity, sample/pdf agreement, and the whole kit over a grid with
// the extreme exponents and wi up to 89.9 degrees.
#include <gtest/gtest.h>

#include "materials/bsdf/phong.h"
#include "validation/bsdf_check.h"

namespace scatterlab {
namespace {

const Vec3d Wi = directionFromDegrees(30, 0);

TEST(Phong, MatchesLafortuneWillemsFormula) {
  const PhongBsdf model(Rgb(0.2, 0.3, 0.4), Rgb(0.5), 20.0);
  // f = kd/pi + ks (n+2)/(2pi) cos^n(alpha), alpha between wo and the mirror of wi.
  const Vec3d wo = directionFromDegrees(40, 170);
  const Vec3d mirror(-Wi.x, -Wi.y, Wi.z);
  const double cosAlpha = mirror.x * wo.x + mirror.y * wo.y + mirror.z * wo.z;
  const double lobe = 0.5 * 22.0 / (2.0 * Pi) * std::pow(cosAlpha, 20.0);
  EXPECT_NEAR(model.eval(Wi, wo).x, 0.2 / Pi + lobe, 1e-14);
  EXPECT_NEAR(model.eval(Wi, wo).z, 0.4 / Pi + lobe, 1e-14);
  // At the mirror direction the lobe is at its peak, ks (n+2)/(2 pi).
  EXPECT_NEAR(model.eval(Wi, mirror).y, 0.3 / Pi + 0.5 * 22.0 / (2.0 * Pi), 1e-13);
  // Behind the mirror cone: only the diffuse term.
  EXPECT_NEAR(model.eval(Wi, directionFromDegrees(60, 0)).x, 0.2 / Pi, 1e-15);
  EXPECT_DOUBLE_EQ(model.eval(Wi, wo).x, model.eval(wo, Wi).x);
}

TEST(BlinnPhong, MatchesNganFormulaAtFixedDirections) {
  const double kd = 0.0145, ks = 0.05, n = 300.0;
  const BlinnPhongBsdf model(Rgb(kd), Rgb(ks), n);
  for (auto [ti, pi, to, po] : std::vector<std::array<double, 4>>{{30, 0, 32, 180}, {10, 40, 5, 200}, {60, 0, 58, 175}}) {
    const Vec3d wi = directionFromDegrees(ti, pi), wo = directionFromDegrees(to, po);
    // f = rho_d / pi + rho_s (n+2)/(2 pi) (N.H)^n, H the half vector.
    const Vec3d sum = wi + wo;
    const double cosThetaH = sum.z / std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
    const double expected = kd / Pi + ks * (n + 2.0) / (2.0 * Pi) * std::pow(cosThetaH, n);
    EXPECT_NEAR(model.eval(wi, wo).x, expected, 1e-12 * expected);
    EXPECT_DOUBLE_EQ(model.eval(wi, wo).x, model.eval(wo, wi).x);
  }
  // Exactly at the mirror direction, N.H = 1.
  EXPECT_NEAR(model.eval(Wi, Vec3d(-Wi.x, -Wi.y, Wi.z)).x, kd / Pi + ks * (n + 2.0) / (2.0 * Pi), 1e-12);
}

TEST(PhongFamily, SampleAgreesWithEvalAndPdfAndFailsBelow) {
  const PhongBsdf phong(Rgb(0.3), Rgb(0.6), 100.0);
  const BlinnPhongBsdf blinn(Rgb(0.3), Rgb(0.1), 100.0);
  for (const BsdfModel* model : std::initializer_list<const BsdfModel*>{&phong, &blinn}) {
    for (double uLobe : {0.1, 0.9}) {
      const auto s = model->sample(directionFromDegrees(45, 20), uLobe, {0.3, 0.6});
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->pdf, model->pdf(directionFromDegrees(45, 20), s->wo), 1e-12 * s->pdf);
    }
    EXPECT_FALSE(model->sample(Vec3d(0, 0, -1), 0.5, {0.5, 0.5}));
    EXPECT_EQ(model->pdf(Vec3d(0, 0.6, -0.8), Vec3d(0, 0, 1)), 0.0);
    EXPECT_EQ(model->eval(Vec3d(0, 0, 1), Vec3d(0, 0.6, -0.8)), Rgb(0.0));
  }
}

struct PhongCase {
  double kd, ks, n, wiTheta;
};

// The kit at 1e6 samples costs about 2 s per (parameters, wi) on this machine; each test runs
// the hard corners (sharpest lobe at grazing incidence, n = 0, all-specular) within CI's budget.
// kd + ks <= 1 keeps Phong's albedo <= 1, kd + 4 ks <= 1 Blinn-Phong's.
const std::vector<PhongCase> PhongCorners{{0.2, 0.8, 10000.0, 89.9}, {0.5, 0.5, 0.0, 0.0}, {0.0, 1.0, 1.0, 45.0}};
const std::vector<PhongCase> BlinnCorners{{0.1, 0.2, 100000.0, 89.9}, {0.0, 0.2, 10.0, 45.0}};

template <typename Model> void runPhongKit(const std::string& name, const std::vector<PhongCase>& cases, int chiSquareTests) {
  BsdfCheckOptions o;
  o.samples = 1'000'000;
  o.thetaBins = 64;
  o.phiBins = 128;
  o.seed = 11;
  o.chiSquareTestCount = chiSquareTests;
  for (const PhongCase& c : cases) {
    o.wiThetaDeg = {c.wiTheta};
    const std::string label = name + " kd=" + std::to_string(c.kd) + " ks=" + std::to_string(c.ks) + " n=" + std::to_string(c.n);
    const CheckReport report = runBsdfChecks(Model(Rgb(c.kd), Rgb(c.ks), c.n), label, o);
    EXPECT_TRUE(report.passed()) << formatTable(report);
  }
}

// Sidak over every chi-square test of this file.
const int DefaultChiSquareTests = int(PhongCorners.size() + BlinnCorners.size());

TEST(PhongKit, PassesAtHardCorners) { runPhongKit<PhongBsdf>("phong", PhongCorners, DefaultChiSquareTests); }
TEST(BlinnPhongKit, PassesAtHardCorners) {
  runPhongKit<BlinnPhongBsdf>("blinn-phong", BlinnCorners, DefaultChiSquareTests);
}

}  // namespace
}  // namespace scatterlab
