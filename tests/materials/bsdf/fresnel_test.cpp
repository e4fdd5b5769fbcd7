#include "materials/bsdf/fresnel.h"

#include <complex>

#include <ceres/jet.h>
#include <gtest/gtest.h>

namespace scatterlab {
namespace fresnel_test {

using Jet = ceres::Jet<double, 2>;

// The Fresnel equations in complex arithmetic, straight from their textbook form (Born &
// Wolf, "Principles of Optics", section 13.2): an independent reference for the
// real-arithmetic conductor formula.
double complexFresnel(double cosThetaI, std::complex<double> eta) {
  const double sin2 = 1.0 - cosThetaI * cosThetaI;
  const std::complex<double> etaCosT = std::sqrt(eta * eta - sin2);  // eta cos theta_t
  const std::complex<double> rs = (cosThetaI - etaCosT) / (cosThetaI + etaCosT);
  const std::complex<double> rp = (eta * eta * cosThetaI - etaCosT) / (eta * eta * cosThetaI + etaCosT);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(FresnelDielectric, NormalIncidenceIsSquaredIndexContrast) {
  for (const double eta : {1.0, 1.1, 1.33, 1.5, 2.42, 1.0 / 1.5}) {
    const double expected = sqr((eta - 1.0) / (eta + 1.0));
    EXPECT_NEAR(fresnelDielectric(1.0, eta), expected, 1e-15) << "eta " << eta;
  }
}

TEST(FresnelDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  // Inside glass (eta 1.5, light arriving from below): critical angle asin(1 / 1.5).
  const double criticalCos = std::sqrt(1.0 - 1.0 / (1.5 * 1.5));
  for (const double cosTheta : {0.0, 0.1, 0.5, criticalCos * (1.0 - 1e-9)})
    EXPECT_EQ(fresnelDielectric(-cosTheta, 1.5), 1.0) << "cos " << cosTheta;
  EXPECT_LT(fresnelDielectric(-criticalCos * (1.0 + 1e-6), 1.5), 1.0);
  EXPECT_LT(fresnelDielectric(-1.0, 1.5), 0.05);
}

TEST(FresnelDielectric, InsideIsOutsideWithInvertedIndex) {
  for (const double eta : {1.33, 1.5, 2.0}) {
    for (double cosTheta = 0.0; cosTheta <= 1.0; cosTheta += 0.0625) {
      EXPECT_DOUBLE_EQ(fresnelDielectric(-cosTheta, eta), fresnelDielectric(cosTheta, 1.0 / eta));
    }
  }
}

TEST(FresnelDielectric, SameReflectanceFromBothSidesAlongTheRefractedPath) {
  // Reversibility (Stokes relations): light entering at theta_i and light leaving along the
  // refracted direction theta_t are reflected in the same proportion.
  for (const double eta : {1.33, 1.5, 2.42}) {
    for (double cosI = 0.05; cosI <= 1.0; cosI += 0.05) {
      const double cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / (eta * eta));
      EXPECT_NEAR(fresnelDielectric(cosI, eta), fresnelDielectric(-cosT, eta), 1e-14);
    }
  }
}

TEST(FresnelConductor, MatchesComplexFresnelEquations) {
  for (const double n : {0.05, 0.2, 0.5, 1.0, 1.5, 3.0}) {
    for (const double k : {0.0, 0.1, 1.0, 3.0, 10.0}) {
      // From 1/32: at grazing incidence the complex form is 0/0 for eta = 1 (tested below).
      for (double cosTheta = 1.0 / 32.0; cosTheta <= 1.0; cosTheta += 1.0 / 32.0) {
        EXPECT_NEAR(fresnelConductor(cosTheta, n, k), complexFresnel(cosTheta, {n, k}), 1e-13)
            << "n " << n << " k " << k << " cos " << cosTheta;
      }
    }
  }
}

TEST(FresnelConductor, ReducesToDielectricWithoutAbsorption) {
  for (const double eta : {0.5, 1.0 / 1.33, 1.2, 1.5, 2.42}) {
    for (double cosTheta = 0.0; cosTheta <= 1.0; cosTheta += 1.0 / 64.0)
      EXPECT_NEAR(fresnelConductor(cosTheta, eta, 0.0), fresnelDielectric(cosTheta, eta), 1e-14)
          << "eta " << eta << " cos " << cosTheta;
  }
}

TEST(FresnelConductor, NormalIncidenceClosedForm) {
  for (const double n : {0.15, 0.5, 1.0, 2.5}) {
    for (const double k : {0.0, 0.5, 3.0, 8.0}) {
      const double expected = (sqr(n - 1.0) + k * k) / (sqr(n + 1.0) + k * k);
      EXPECT_NEAR(fresnelConductor(1.0, n, k), expected, 1e-15);
    }
  }
}

TEST(FresnelConductor, GrazingIncidenceReflectsEverything) {
  for (const double n : {0.15, 1.0, 2.5})
    for (const double k : {0.0, 0.5, 8.0}) EXPECT_NEAR(fresnelConductor(0.0, n, k), 1.0, 1e-15);
}

TEST(FresnelConductor, RgbIsPerChannel) {
  const Rgb eta(0.2, 0.9, 1.4), k(3.9, 2.4, 1.6);
  const Rgb f = fresnelConductor(0.3, eta, k);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], fresnelConductor(0.3, eta[c], k[c]));
}

TEST(FresnelSchlick, EndpointsAreF0AndOne) {
  for (const double f0 : {0.0, 0.04, 0.5, 1.0}) {
    EXPECT_DOUBLE_EQ(fresnelSchlick(f0, 1.0), f0);
    EXPECT_DOUBLE_EQ(fresnelSchlick(f0, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(fresnelSchlick(f0, 0.5), f0 + (1.0 - f0) / 32.0);
  }
  const Rgb f = fresnelSchlick(Rgb(0.04, 0.5, 0.9), 0.0);
  EXPECT_EQ(f, Rgb(1.0));
}

// The kernels instantiated with ceres::Jet (the fitter's scalar): same value as double, and
// derivatives with respect to (eta, k) that agree with central differences, and stay finite
// at the singular points (grazing, normal incidence, the TIR boundary, k = 0 at eta = sin).
TEST(FresnelJet, ConductorDerivativesAreFiniteAndCorrect) {
  const double h = 1e-6;
  for (const double cosTheta : {0.0, 1e-6, 0.3, 0.8, 1.0}) {
    for (const auto& [n, k] : {std::pair{0.2, 3.9}, std::pair{1.5, 0.0}, std::pair{0.8, 0.0},
                               std::pair{std::sqrt(1.0 - 0.3 * 0.3), 0.0}}) {
      const Jet f = fresnelConductor(Jet(cosTheta), Jet(n, 0), Jet(k, 1));
      ASSERT_TRUE(ceres::isfinite(f)) << "cos " << cosTheta << " n " << n << " k " << k;
      EXPECT_NEAR(f.a, fresnelConductor(cosTheta, n, k), 1e-15);
      const bool smooth = k > 0.0 || std::abs(n * n - (1.0 - cosTheta * cosTheta)) > 1e-3;
      if (!smooth) continue;
      const double dn =
          (fresnelConductor(cosTheta, n + h, k) - fresnelConductor(cosTheta, n - h, k)) / (2 * h);
      EXPECT_NEAR(f.v[0], dn, 1e-6 * std::max(1.0, std::abs(dn)));
      if (k > h) {
        const double dk =
            (fresnelConductor(cosTheta, n, k + h) - fresnelConductor(cosTheta, n, k - h)) / (2 * h);
        EXPECT_NEAR(f.v[1], dk, 1e-6 * std::max(1.0, std::abs(dk)));
      }
    }
  }
}

TEST(FresnelJet, DielectricDerivativesAreFiniteAndCorrect) {
  const double h = 1e-6;
  for (const double cosTheta : {-1.0, -0.8, -0.2, 0.0, 0.3, 1.0}) {
    for (const double eta : {1.0, 1.33, 1.5}) {
      const Jet f = fresnelDielectric(Jet(cosTheta), Jet(eta, 0));
      ASSERT_TRUE(ceres::isfinite(f)) << "cos " << cosTheta << " eta " << eta;
      EXPECT_NEAR(f.a, fresnelDielectric(cosTheta, eta), 1e-15);
      const double de =
          (fresnelDielectric(cosTheta, eta + h) - fresnelDielectric(cosTheta, eta - h)) / (2 * h);
      if (std::abs(cosTheta) > 0.5) {
        EXPECT_NEAR(f.v[0], de, 1e-6);
      }
    }
  }
}

}  // namespace fresnel_test
}  // namespace scatterlab
