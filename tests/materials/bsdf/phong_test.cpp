// Normalised Phong and Ngan's Blinn-Phong: values at fixed directions computed by hand from
// the papers' formulas, reciprocity, sample/pdf agreement, and the whole kit over a grid with
// the extreme exponents and wi up to 89.9 degrees.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/phong.h"

namespace scatterlab {
namespace phong_test {

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
  for (auto [ti, pi, to, po] :
       std::vector<std::array<double, 4>>{{30, 0, 32, 180}, {10, 40, 5, 200}, {60, 0, 58, 175}}) {
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

// ---- The kit ----

// kd + ks <= 1 keeps Phong's albedo <= 1, kd + 4 ks <= 1 Blinn-Phong's. The corners: the
// sharpest lobes (n = 1e4 and Ngan's 1e5) and n = 0 (a uniform lobe), all-specular, and a
// typical material; every case at normal, oblique and grazing incidence.
struct PhongCase {
  bool blinn;
  double kd, ks, n;
};
std::string name(const PhongCase& c) {
  return std::string(c.blinn ? "BlinnPhong" : "Phong") + "_kd" + catalog_suite::number(c.kd) + "_ks" +
         catalog_suite::number(c.ks) + "_n" + catalog_suite::number(c.n);
}
void PrintTo(const PhongCase& c, std::ostream* os) { *os << name(c); }
std::vector<PhongCase> grid() {
  return {{false, 0.2, 0.8, 10000.0}, {false, 0.5, 0.5, 0.0}, {false, 0.0, 1.0, 1.0}, {false, 0.3, 0.6, 50.0},
          {true, 0.1, 0.2, 100000.0}, {true, 0.0, 0.2, 10.0}, {true, 0.5, 0.1, 100.0}};
}
const std::vector<double> KitAngles{0, 60, 89.9};
const catalog_suite::ChiSquareSuite Suite{"phong-kit", int(grid().size() * KitAngles.size())};

class PhongKit : public ::testing::TestWithParam<PhongCase> {};

TEST_P(PhongKit, PassesEveryCheck) {
  const PhongCase& c = GetParam();
  BsdfCheckOptions o = Suite.options(11);
  o.wiThetaDeg = KitAngles;
  if (c.blinn)
    catalog_suite::expectPasses(BlinnPhongBsdf(Rgb(c.kd), Rgb(c.ks), c.n), name(c), o);
  else
    catalog_suite::expectPasses(PhongBsdf(Rgb(c.kd), Rgb(c.ks), c.n), name(c), o);
}

INSTANTIATE_TEST_SUITE_P(Grid, PhongKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<PhongCase>& info) { return name(info.param); });

TEST(PhongControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(
      Suite, {{"type", "phong"}, {"kd", 0.3}, {"ks", 0.6}, {"exponent", 40}}, 30.0);
}
TEST(BlinnPhongControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(
      Suite, {{"type", "blinn-phong"}, {"kd", 0.2}, {"ks", 0.2}, {"exponent", 200}}, 70.0);
}

}  // namespace phong_test
}  // namespace scatterlab
