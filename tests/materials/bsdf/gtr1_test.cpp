// GTR1 (Burley 2012 eq. 4 and appendix B): D integrates to 1 against cos theta_m (by
// quadrature, independent of the closed-form CDF the sampler inverts), the sampler round-trips
// through its inverse, and its samples follow pdfClassic (chi-square; a mismatched alpha is
// rejected).
#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <cmath>

#include "catalog_suite.h"
#include "materials/bsdf/gtr1.h"
#include "materials/core/quadrature.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace gtr1_test {

// D of a unit normal at polar angle theta (D does not depend on the azimuth).
double gtr1AtSin2(const Gtr1Distribution<double>& d, double sin2) {
  return d.D(Vec3d(std::sqrt(sin2), 0.0, std::sqrt(1.0 - sin2)));
}

// integral D cos theta dm = pi integral_0^1 D ds over s = sin^2 theta (ds = 2 sin cos dtheta),
// on decades of s so that the alpha^2-wide peak at s = 0 is resolved.
double projectedIntegral(double alpha) {
  const Gtr1Distribution<double> d(alpha);
  QuadratureOptions q;
  q.relativeTolerance = 1e-10;
  double total = 0.0, lo = 0.0;
  for (int exponent = -14; exponent <= 0; ++exponent) {
    const double hi = std::pow(10.0, exponent);
    total += adaptiveSimpson([&](double s) { return gtr1AtSin2(d, s); }, lo, hi, q);
    lo = hi;
  }
  return Pi * total;
}

TEST(Gtr1, IsNormalisedAgainstCosTheta) {
  // 0.99999 is inside the series branch of (alpha^2 - 1) / ln(alpha^2), 1 is its limit.
  for (double alpha : {0.001, 0.01, 0.1, 0.5, 0.99999, 1.0})
    EXPECT_NEAR(projectedIntegral(alpha), 1.0, 1e-8) << alpha;
}

TEST(Gtr1, MatchesBurleysFormulaAtFixedNormals) {
  for (double alpha : {0.001, 0.1, 0.7}) {
    const Gtr1Distribution<double> d(alpha);
    for (double thetaDeg : {0.0, 1.0, 30.0, 80.0}) {
      const double c = std::cos(radians(thetaDeg));
      const double a2 = alpha * alpha;
      const double expected = (a2 - 1.0) / (Pi * std::log(a2) * (1.0 + (a2 - 1.0) * c * c));
      // The paper's 1 + (alpha^2 - 1) cos^2 cancels near the pole (relative error ~1e-16 / alpha^2);
      // gtr1.h writes it as sin^2 + alpha^2 cos^2.
      EXPECT_NEAR(d.D(directionFromDegrees(thetaDeg, 40)), expected, 1e-9 * expected)
          << alpha << " " << thetaDeg;
    }
  }
}

// Either side of the switch to the series at |alpha^2 - 1| = 1e-4: continuous to the series'
// truncation error, and the derivative with respect to alpha stays finite at alpha = 1.
TEST(Gtr1, SeriesNearAlphaOneIsContinuousAndDifferentiable) {
  const Vec3d m = directionFromDegrees(50, 0);
  const double below = Gtr1Distribution<double>(std::sqrt(1.0 - 1.0001e-4)).D(m);
  const double above = Gtr1Distribution<double>(std::sqrt(1.0 - 0.9999e-4)).D(m);
  EXPECT_NEAR(below, above, 1e-8);
  using Jet = ceres::Jet<double, 1>;
  const Jet d = Gtr1Distribution<Jet>(Jet(1.0, 0)).D(Vec3<Jet>(Jet(m.x), Jet(m.y), Jet(m.z)));
  EXPECT_NEAR(d.a, InvPi, 1e-15);
  EXPECT_TRUE(std::isfinite(d.v[0]));
}

TEST(Gtr1, SamplerRoundTripsThroughItsInverse) {
  for (double alpha : {0.001, 0.1, 0.5, 1.0}) {
    const Gtr1Distribution<double> d(alpha);
    for (double u0 : {1e-9, 1e-4, 0.1, 0.37, 0.5, 0.81, 0.999}) {
      for (double u1 : {0.01, 0.3, 0.66, 0.99}) {
        const Vec3d m = d.sampleClassic({u0, u1});
        EXPECT_NEAR(glm::length(m), 1.0, 1e-14);
        const Vec2d back = d.invertClassic(m);
        EXPECT_NEAR(back.x, u0, 1e-10 * u0 + 1e-16) << alpha << " " << u0;  // relative, also near the pole
        EXPECT_NEAR(back.y, u1, 1e-12) << alpha << " " << u1;
      }
    }
  }
}

// Chi-square tests of the sampler, one suite (catalog_suite.h).
struct SamplerCase {
  double alpha;
  int thetaBins, phiBins;
};
const std::vector<SamplerCase> SamplerCases{{0.001, 64, 128}, {0.1, 37, 83}, {1.0, 64, 128}};
const catalog_suite::ChiSquareSuite Suite{"gtr1", int(SamplerCases.size())};

ChiSquareOptions chiSquareOptions(const SamplerCase& c) {
  ChiSquareOptions o;
  o.grid = {c.thetaBins, c.phiBins};
  o.sampleCount = 500000;
  o.seed = 11;
  o.threshold = Suite.threshold();
  return o;
}

ChiSquareResult samplerAgainstPdf(const Gtr1Distribution<double>& sampler,
                                  const Gtr1Distribution<double>& density, const ChiSquareOptions& o) {
  const auto draw = [&](CounterRng& rng) -> std::optional<DirectionSample> {
    const Vec3d m = sampler.sampleClassic(rng.uniform2D());
    const double pdf = density.pdfClassic(m);
    if (!(pdf > 0)) return std::nullopt;
    return DirectionSample{m, pdf};
  };
  return sphericalChiSquareTest(
      draw, [&](const Vec3d& m) { return density.pdfClassic(m); }, o);
}

TEST(Gtr1, SamplerFollowsItsPdf) {
  for (const SamplerCase& c : SamplerCases) {
    const Gtr1Distribution<double> d(c.alpha);
    const ChiSquareResult r = samplerAgainstPdf(d, d, chiSquareOptions(c));
    EXPECT_TRUE(r.passed) << "alpha " << c.alpha << ": chi2 " << r.statistic << " dof " << r.dof << " p "
                          << r.pValue << " " << r.failure;
  }
}

TEST(Gtr1, ChiSquareRejectsASamplerWithTheWrongAlpha) {
  const ChiSquareResult r = samplerAgainstPdf(Gtr1Distribution<double>(0.11), Gtr1Distribution<double>(0.1),
                                              chiSquareOptions(SamplerCases[0]));
  EXPECT_FALSE(r.passed) << "chi2 " << r.statistic << " p " << r.pValue;
}

}  // namespace gtr1_test
}  // namespace scatterlab
