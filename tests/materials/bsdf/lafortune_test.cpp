// Lafortune lobes and Ngan's normalised single lobe: values at fixed directions computed by
// hand from the formulas, reciprocity, and the whole kit (one lobe, anisotropic raw lobe, two
// lobes) with the extreme exponents and wi up to 89.9 degrees.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/lafortune.h"

namespace scatterlab {
namespace lafortune_test {

TEST(Lafortune, RawLobeMatchesLafortune1997Eq4) {
  const LafortuneBsdf model(Rgb(0.1), {LafortuneLobe{Rgb(0.4), Vec3d(-0.9, -0.5, 0.7), 12.0}},
                            LafortuneNormalization::None);
  const Vec3d wi = directionFromDegrees(35, 20), wo = directionFromDegrees(30, 190);
  const double d = -0.9 * wi.x * wo.x - 0.5 * wi.y * wo.y + 0.7 * wi.z * wo.z;
  ASSERT_GT(d, 0.0);
  EXPECT_NEAR(model.eval(wi, wo).x, 0.1 / Pi + 0.4 * std::pow(d, 12.0), 1e-14);
  EXPECT_DOUBLE_EQ(model.eval(wi, wo).x, model.eval(wo, wi).x);
  // A lobe whose dot product is negative contributes nothing.
  const Vec3d away = directionFromDegrees(80, 20);
  ASSERT_LT(-0.9 * wi.x * away.x - 0.5 * wi.y * away.y + 0.7 * wi.z * away.z, 0.0);
  EXPECT_NEAR(model.eval(wi, away).x, 0.1 / Pi, 1e-15);
}

TEST(Lafortune, NganLobeMatchesPublishedFitFormula) {
  // blue-acrylic from published-fits/ngan_lafortune.fit.
  const Rgb kd(0.0145, 0.0332, 0.064), rho(0.0238, 0.0164, 0.01);
  const double cxy = -0.577, cz = 0.577, n = 4060.0;
  const LafortuneBsdf model(kd, {LafortuneLobe{rho, Vec3d(cxy, cxy, cz), n}}, LafortuneNormalization::Ngan);
  const Vec3d wi = directionFromDegrees(25, 60);
  // At the mirror direction C.(wi*wo) = 0.577 = sqrt(max(Cz^2, Cxy^2)): the lobe is (n+2)/(2pi) rho.
  const Vec3d mirror(-wi.x, -wi.y, wi.z);
  EXPECT_NEAR(model.eval(wi, mirror).y, kd.y / Pi + rho.y * (n + 2.0) / (2.0 * Pi), 1e-9);
  // Slightly off the mirror: rho (n+2)/(2pi) (d / 0.577)^n.
  const Vec3d wo = directionFromDegrees(25.5, 240.3);
  const double d = cxy * (wi.x * wo.x + wi.y * wo.y) + cz * wi.z * wo.z;
  const double expected = kd.x / Pi + rho.x * (n + 2.0) / (2.0 * Pi) * std::pow(d / 0.577, n);
  EXPECT_NEAR(model.eval(wi, wo).x, expected, 1e-12 * expected);
  EXPECT_DOUBLE_EQ(model.eval(wi, wo).x, model.eval(wo, wi).x);
}

TEST(Lafortune, SampleAgreesWithPdfAndFailsBelow) {
  const LafortuneBsdf model(
      Rgb(0.2),
      {LafortuneLobe{Rgb(0.3), Vec3d(-1, -1, 1), 30.0}, LafortuneLobe{Rgb(0.2), Vec3d(0.8, 0.8, 0.9), 5.0}},
      LafortuneNormalization::Ngan);
  const Vec3d wi = directionFromDegrees(50, 10);
  for (double uLobe : {0.05, 0.5, 0.95}) {
    const auto s = model.sample(wi, uLobe, {0.4, 0.3});
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf, model.pdf(wi, s->wo), 1e-12 * s->pdf);
  }
  EXPECT_FALSE(model.sample(Vec3d(0, 0, -1), 0.5, {0.5, 0.5}));
  EXPECT_EQ(model.eval(wi, Vec3d(0, 0.6, -0.8)), Rgb(0.0));
}

struct LafortuneCase {
  std::string name;
  Rgb kd;
  std::vector<LafortuneLobe> lobes;
  LafortuneNormalization normalization;
};
void PrintTo(const LafortuneCase& c, std::ostream* os) { *os << c.name; }

std::vector<LafortuneCase> grid() {
  return {
      {"ngan-blue-acrylic",
       Rgb(0.0145, 0.0332, 0.064),
       {{Rgb(0.0238, 0.0164, 0.01), Vec3d(-0.577, -0.577, 0.577), 4060.0}},
       LafortuneNormalization::Ngan},
      {"ngan-n0", Rgb(0.3), {{Rgb(0.6), Vec3d(-1, -1, 1), 0.0}}, LafortuneNormalization::Ngan},
      {"ngan-n10000", Rgb(0.1), {{Rgb(0.9), Vec3d(-0.7, -0.7, 0.5), 10000.0}}, LafortuneNormalization::Ngan},
      {"raw-anisotropic", Rgb(0.2), {{Rgb(0.5), Vec3d(-0.9, -0.5, 0.7), 20.0}}, LafortuneNormalization::None},
      {"ngan-two-lobes",
       Rgb(0.2),
       {{Rgb(0.3), Vec3d(-1, -1, 1), 30.0}, {Rgb(0.2), Vec3d(0.8, 0.8, 0.9), 5.0}},
       LafortuneNormalization::Ngan},
  };
}

const std::vector<double> KitAngles{0, 60, 89.9};
const catalog_suite::ChiSquareSuite Suite{"lafortune-kit", int(grid().size() * KitAngles.size())};

class LafortuneKit : public ::testing::TestWithParam<LafortuneCase> {};

TEST_P(LafortuneKit, PassesEveryCheck) {
  const LafortuneCase& c = GetParam();
  BsdfCheckOptions o = Suite.options(13);
  o.wiThetaDeg = KitAngles;
  catalog_suite::expectPasses(LafortuneBsdf(c.kd, c.lobes, c.normalization), "lafortune-" + c.name, o);
}

INSTANTIATE_TEST_SUITE_P(Grid, LafortuneKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<LafortuneCase>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n) ch = ch == '-' ? '_' : ch;
                           return n;
                         });

TEST(LafortuneControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(Suite,
                                        {{"type", "lafortune"},
                                         {"kd", 0.2},
                                         {"ks", 0.5},
                                         {"cx", -0.8},
                                         {"cy", -0.8},
                                         {"cz", 0.9},
                                         {"exponent", 30}},
                                        50.0);
}

}  // namespace lafortune_test
}  // namespace scatterlab
