// EON (eon.h): the paper's expressions written out independently at fixed directions, the
// analytic FON albedo and its average against quadrature, the fit's error, the white
// furnace, reciprocity, the kernel with Jets, the sampler against plain cosine sampling, the
// registry entry, and the whole kit with negative controls.
#include "materials/bsdf/eon.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>
#include <cstdio>

#include "catalog_suite.h"
#include "materials/core/quadrature.h"
#include "materials/core/rng.h"

namespace scatterlab {
namespace eon_test {

// ---- The paper's expressions, with angles (JCGT 2025, eq. 3-10) ----

constexpr double PaperC1 = 0.5 - 2.0 / (3.0 * Pi), PaperC2 = 2.0 / 3.0 - 28.0 / (15.0 * Pi);

double paperAlbedoAnalytic(double mu, double r) {
  const double a = 1.0 / (1.0 + PaperC1 * r), b = r * a;
  const double s = std::sqrt(1.0 - mu * mu);
  const double g = s * (std::acos(mu) - s * mu) + (2.0 / 3.0) * ((s / mu) * (1.0 - s * s * s) - s);
  return a + (b / Pi) * g;
}

double paperAlbedoFitted(double mu, double r) {
  const double m = 1.0 - mu, m2 = m * m;
  // The paper's 2 x 2 coefficient matrix applied to (m, m^2), dotted with (1, m^2).
  const double row0 = 0.0571085289 * m + 0.491881867 * m2, row1 = -0.332181442 * m + 0.0714429953 * m2;
  return (1.0 + r * (row0 + row1 * m2)) / (1.0 + PaperC1 * r);
}

double paperEon(double rho, double r, double thetaI, double phiI, double thetaO, double phiO, bool fitted) {
  const double muI = std::cos(thetaI), muO = std::cos(thetaO);
  const double s = std::sin(thetaI) * std::sin(thetaO) * std::cos(phiI - phiO);
  const double sOverT = s > 0 ? s / std::max(muI, muO) : s;
  const double a = 1.0 / (1.0 + PaperC1 * r);
  const double single = rho / Pi * a * (1.0 + r * sOverT);
  const double eI = fitted ? paperAlbedoFitted(muI, r) : paperAlbedoAnalytic(muI, r);
  const double eO = fitted ? paperAlbedoFitted(muO, r) : paperAlbedoAnalytic(muO, r);
  const double eAvg = a * (1.0 + PaperC2 * r);
  // r = 0 loses nothing: no lobe (the paper's 1e-7 guards would leave ~2e-8 of one).
  if (!(1.0 - eAvg > 0)) return single;
  const double rhoMs = rho * rho * eAvg / (1.0 - rho * (1.0 - eAvg));
  return single + rhoMs / Pi * (1.0 - eI) * (1.0 - eO) / (1.0 - eAvg);
}

TEST(Eon, EqualsThePapersExpressions) {
  for (const bool fitted : {true, false})
    for (const double r : {0.0, 0.3, 1.0})
      for (const auto& [ti, pi, to, po] : std::vector<std::array<double, 4>>{{10, 0, 50, 20},
                                                                             {70, 30, 20, 10},
                                                                             {85, 0, 80, 180},
                                                                             {40, 90, 60, 250},
                                                                             {60, 0, 60, 0},
                                                                             {1, 0, 30, 0}}) {
        const Vec3d wi = directionFromDegrees(ti, pi), wo = directionFromDegrees(to, po);
        const double expected = paperEon(0.7, r, radians(ti), radians(pi), radians(to), radians(po), fitted);
        const EonBsdf model(Rgb(0.7), r, fitted ? EonAlbedo::Fitted : EonAlbedo::Analytic);
        EXPECT_NEAR(model.eval(wi, wo).x, expected, 1e-13) << ti << " " << to << " r " << r;
      }
  // r = 0 is Lambert.
  EXPECT_DOUBLE_EQ(EonBsdf(Rgb(0.7), 0.0).eval(directionFromDegrees(30, 0), directionFromDegrees(70, 100)).x,
                   0.7 / Pi);
  EXPECT_EQ(EonBsdf(Rgb(0.7), 0.5).eval(directionFromDegrees(30, 0), Vec3d(0.6, 0, -0.8)), Rgb(0.0));
  EXPECT_FALSE(EonBsdf(Rgb(0.7), 0.5).sample(Vec3d(0, 0, -1), 0.5, {0.5, 0.5}));
}

// The stable rewrite of (S / mu)(1 - S^3) agrees with the paper's form, and reaches E = 1 at
// grazing, where the paper's form is 0 / 0.
TEST(Eon, AnalyticAlbedoMatchesThePaperAndIsOneAtGrazing) {
  for (const double r : {0.2, 1.0}) {
    for (const double mu : {1.0, 0.8, 0.3, 0.05, 1e-3})
      EXPECT_NEAR(eon::fonAlbedoAnalytic(mu, r), paperAlbedoAnalytic(mu, r), 1e-12) << mu;
    EXPECT_NEAR(eon::fonAlbedoAnalytic(0.0, r), 1.0, 1e-15);
    EXPECT_NEAR(eon::fonAlbedoFitted(0.5, r), paperAlbedoFitted(0.5, r), 1e-15);
  }
}

QuadratureOptions hemisphereOptions() {
  QuadratureOptions q;
  q.relativeTolerance = 1e-9;
  q.absoluteTolerance = 1e-12;
  q.minDepth = 4;
  return q;
}

// integral over the hemisphere of f(wo) cos theta_o.
template <typename F> double hemisphereIntegral(const F& f) {
  return adaptiveSimpson2D(
      [&](double cosTheta, double phi) {
        return f(sphericalDirection(safeSqrt(1.0 - cosTheta * cosTheta), cosTheta, phi)) * cosTheta;
      },
      0.0, 1.0, -Pi, Pi, hemisphereOptions());
}

// Eq. 6 is the directional albedo of FON's single scattering (rho = 1), and eq. 7 its cosine-
// weighted average: both against quadrature of the model itself.
TEST(Eon, AnalyticAlbedoAndAverageAreFonsIntegrals) {
  for (const double r : {0.25, 0.6, 1.0}) {
    const EonBsdf model(Rgb(1.0), r);
    for (const double theta : {0.0, 45.0, 80.0, 89.5}) {
      const Vec3d wi = directionFromDegrees(theta, 10);
      const double singleScattering = hemisphereIntegral([&](const Vec3d& wo) {
        const double s = glm::dot(wi, wo) - wi.z * wo.z;
        return eon::fonA(r) * InvPi * (1.0 + r * (s > 0 ? s / std::max(wi.z, wo.z) : s));
      });
      EXPECT_NEAR(singleScattering, eon::fonAlbedoAnalytic(wi.z, r), 1e-7) << "r " << r << " theta " << theta;
    }
    QuadratureOptions q = hemisphereOptions();
    const double average =
        2.0 * adaptiveSimpson([&](double mu) { return eon::fonAlbedoAnalytic(mu, r) * mu; }, 0.0, 1.0, q);
    EXPECT_NEAR(average, eon::fonAverageAlbedo(r), 1e-10) << r;
  }
}

// The fit's error, stated in eon.h as 4.7e-4 at most; on a 101 x 1001 grid of (r, mu).
TEST(Eon, FittedAlbedoIsWithinItsStatedError) {
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 1000; ++j) {
      const double r = i / 100.0, mu = j / 1000.0;
      worst = std::max(worst, std::abs(eon::fonAlbedoFitted(mu, r) - eon::fonAlbedoAnalytic(mu, r)));
    }
  EXPECT_LT(worst, 4.8e-4);
  EXPECT_GT(worst, 4.0e-4);  // the bound is tight, not loose
}

// White furnace (docs/validation.md section 3), by quadrature of the model's eval over the
// hemisphere: with the analytic albedo, 1 to the quadrature's accuracy; with the paper's fit,
// 1 within 1e-3, the fit's own error (4.7e-4 at most in E, 5.4e-4 measured in the albedo)
// with a factor 2 for the quadrature.
TEST(Eon, WhiteFurnace) {
  double worstFitted = 0.0;
  for (const double r : {0.0, 0.25, 0.5, 1.0})
    for (const double theta : {0.0, 17.0, 30.0, 41.4, 60.0, 85.0, 89.9}) {
      const Vec3d wi = directionFromDegrees(theta, 30);
      const EonBsdf analytic(Rgb(1.0), r, EonAlbedo::Analytic), fitted(Rgb(1.0), r, EonAlbedo::Fitted);
      EXPECT_TRUE(analytic.isLossless());
      EXPECT_FALSE(fitted.isLossless());
      const double a = hemisphereIntegral([&](const Vec3d& wo) { return analytic.eval(wi, wo).x; });
      const double f = hemisphereIntegral([&](const Vec3d& wo) { return fitted.eval(wi, wo).x; });
      EXPECT_NEAR(a, 1.0, 1e-7) << "analytic r " << r << " theta " << theta;
      EXPECT_NEAR(f, 1.0, 1e-3) << "fitted r " << r << " theta " << theta;
      worstFitted = std::max(worstFitted, std::abs(f - 1.0));
    }
  std::printf("EON white furnace with the fitted albedo: max |albedo - 1| = %.2e\n", worstFitted);
}

TEST(Eon, IsReciprocal) {
  for (const auto albedo : {EonAlbedo::Fitted, EonAlbedo::Analytic}) {
    const EonBsdf model(Rgb(0.9, 0.5, 0.2), 0.8, albedo);
    CounterRng rng(31, 0);
    for (int n = 0; n < 2000; ++n) {
      const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()),
                  wo = sampleUniformHemisphere(rng.uniform2D());
      const Rgb x = model.eval(wi, wo), y = model.eval(wo, wi);
      for (int c = 0; c < 3; ++c) ASSERT_LE(relativeDifference(x[c], y[c]), 1e-13);
    }
  }
}

// The kernel with T = ceres::Jet (fitting): the double value, finite derivatives with respect
// to rho and r, also at r = 0 and at grazing directions.
TEST(Eon, KernelWithJetsMatchesDoubleAndHasFiniteDerivatives) {
  using Jet = ceres::Jet<double, 2>;
  for (const double r : {0.0, 0.4, 1.0})
    for (const auto& [wi, wo] : std::vector<std::pair<Vec3d, Vec3d>>{
             {directionFromDegrees(30, 0), directionFromDegrees(60, 170)},
             {directionFromDegrees(89.99, 0), directionFromDegrees(89.99, 180)},
             {directionFromDegrees(0, 0), directionFromDegrees(45, 45)}}) {
      const RgbT<Jet> rho(Jet(0.6, 0), Jet(0.6, 0), Jet(0.6, 0));
      const RgbT<Jet> f = eonEval<Jet>(rho, Jet(r, 1), wi, wo, EonAlbedo::Fitted);
      const double reference = EonBsdf(Rgb(0.6), r).eval(wi, wo).x;
      EXPECT_NEAR(f.x.a, reference, 1e-14 * std::max(1.0, reference));
      EXPECT_TRUE(ceres::isfinite(f.x)) << r;
    }
}

// The CLTC mixture follows the lobe: at grazing incidence and full roughness, where EON's
// backscattering lobe rises, its sample weights vary far less than cosine sampling's (whose
// weight is pi f); same random numbers, same model.
TEST(Eon, ClippedLtcSamplingBeatsCosineSampling) {
  const EonBsdf model(Rgb(1.0), 1.0);
  for (const double theta : {60.0, 85.0}) {
    const Vec3d wi = directionFromDegrees(theta, 0);
    CounterRng rng(41, 0);
    double sum = 0, sumSq = 0, cosineSum = 0, cosineSumSq = 0;
    const int n = 50000;
    for (int i = 0; i < n; ++i) {
      const double uLobe = rng.uniform();
      const Vec2d u = rng.uniform2D();
      const auto s = model.sample(wi, uLobe, u);
      const double w = s ? s->weight.x : 0.0;
      sum += w;
      sumSq += w * w;
      const Vec3d wo = sampleCosineHemisphere(u);
      const double c = wo.z > 0 ? Pi * model.eval(wi, wo).x : 0.0;
      cosineSum += c;
      cosineSumSq += c * c;
    }
    const double variance = sumSq / n - sqr(sum / n), cosineVariance = cosineSumSq / n - sqr(cosineSum / n);
    std::printf("EON r = 1, theta %g: weight variance CLTC %.3e, cosine %.3e\n", theta, variance,
                cosineVariance);
    EXPECT_LT(variance, 0.5 * cosineVariance) << theta;
  }
}

TEST(Eon, Registry) {
  const auto model = makeBsdf({{"type", "eon"}});
  EXPECT_EQ(model->flags(), LobeFlags::DiffuseReflection);
  EXPECT_EQ(completeMaterial({{"type", "eon"}})["directional_albedo"], "fitted");
  EXPECT_TRUE(makeBsdf({{"type", "eon"}, {"albedo", 1.0}, {"directional_albedo", "analytic"}})->isLossless());
  EXPECT_THROW(makeBsdf({{"type", "eon"}, {"roughness", 1.5}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "eon"}, {"albedo", -0.1}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "eon"}, {"directional_albedo", "exact"}}), MaterialError);
  try {
    makeBsdf({{"type", "eon"}, {"roughness", 2}});
  } catch (const MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("[0, 1]"), std::string::npos) << error.what();
  }
}

// ---- The kit ----

struct KitCase {
  double rho, roughness;
  EonAlbedo albedo;
  std::vector<double> angles{};
};

std::string name(const KitCase& c) {
  return "rho" + catalog_suite::number(c.rho) + "_r" + catalog_suite::number(c.roughness) +
         (c.albedo == EonAlbedo::Fitted ? "_fitted" : "_analytic");
}
void PrintTo(const KitCase& c, std::ostream* os) { *os << name(c); }

// Hard corners: full roughness at normal and grazing incidence (the backscattering peak and
// the clipped LTC's extremes), white with the analytic albedo so the kit adds its furnace
// row, r = 0 (Lambert, pure cosine sampling) and an intermediate roughness.
const std::vector<KitCase>& kitGrid() {
  static const std::vector<KitCase> cases{
      {1.0, 1.0, EonAlbedo::Analytic, {0, 89.9}},
      {0.8, 1.0, EonAlbedo::Fitted, {60}},
      {0.8, 0.4, EonAlbedo::Fitted, {85}},
      {1.0, 0.0, EonAlbedo::Analytic, {30}},
  };
  return cases;
}

int kitChiSquareTests() {
  int count = 0;
  for (const KitCase& c : kitGrid()) count += int(c.angles.size());
  return count;
}

const catalog_suite::ChiSquareSuite Suite{"eon-kit", kitChiSquareTests()};

class EonKit : public ::testing::TestWithParam<KitCase> {};

TEST_P(EonKit, PassesEveryCheck) {
  const KitCase& c = GetParam();
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = c.angles;
  const EonBsdf model(Rgb(c.rho), c.roughness, c.albedo);
  catalog_suite::expectPasses(model, name(c), o);
}

INSTANTIATE_TEST_SUITE_P(Grid, EonKit, ::testing::ValuesIn(kitGrid()),
                         [](const ::testing::TestParamInfo<KitCase>& info) { return name(info.param); });

// At 60 degrees. Closer to the normal the sampler hardly depends on the roughness (at
// normal incidence the LTC matrix changes by 0.1% from r = 0.7 to 0.77), so the 10% roughness
// control is below the chi-square's power there (p = 0.33 at 0 degrees, 0.11 at 30, measured):
// a property of EON's sampler, not a blind spot of the kit.
class EonNegativeControls : public ::testing::TestWithParam<double> {};

TEST_P(EonNegativeControls, AreRejected) {
  catalog_suite::expectControlsRejected(Suite, {{"type", "eon"}, {"roughness", 0.7}}, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Controls, EonNegativeControls, ::testing::Values(60.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return "wi" + std::to_string(int(info.param));
                         });

}  // namespace eon_test
}  // namespace scatterlab
