// ln Gamma and Beta (materials/core/special_functions.h) against the standard library and
// against the Beta function's defining integral by quadrature; and their Jet derivatives
// against central differences. The inverse error functions against std::erf and std::erfc.
#include "materials/core/special_functions.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "materials/core/quadrature.h"

namespace scatterlab {
namespace special_functions_test {

// Stirling's series after the shift errs by < 7e-16; the rounding of its terms (~12.8 for
// x < 10, ~x ln x above) leaves ~1e-14 absolute, or relative for large values.
TEST(SpecialFunctions, LogGammaMatchesStdLgamma) {
  for (const double x : {1e-3, 0.1, 0.5, 1.0, 1.5, 2.0, 3.7, 9.99, 10.0, 10.5, 42.0, 1e3, 1e6}) {
    const double expected = std::lgamma(x);
    EXPECT_NEAR(logGamma(x), expected, 1e-14 * std::max(1.0, std::abs(expected))) << "x = " << x;
  }
}

// B(1 + a, 1 + b) = integral_0^1 u^a (1 - u)^b du, the form the rough dielectric's masking
// uses (smith_transmission.h).
TEST(SpecialFunctions, BetaMatchesItsIntegral) {
  QuadratureOptions q;
  q.relativeTolerance = 1e-12;
  q.absoluteTolerance = 1e-300;
  q.minDepth = 4;
  // Exponents >= 1 or 0: u^a stays smooth enough at the ends for Simpson to reach 1e-12.
  for (const double a : {0.0, 1.5, 4.5, 30.0})
    for (const double b : {0.0, 2.5, 17.0}) {
      const double integral =
          adaptiveSimpson([&](double u) { return std::pow(u, a) * std::pow(1.0 - u, b); }, 0.0, 1.0, q);
      EXPECT_NEAR(betaFunction(1.0 + a, 1.0 + b), integral, 1e-10 * integral) << "a = " << a << " b = " << b;
    }
}

TEST(SpecialFunctions, BetaIsSymmetricToTheLastBitAndKnownValues) {
  EXPECT_EQ(betaFunction(1.3, 7.9), betaFunction(7.9, 1.3));
  EXPECT_NEAR(betaFunction(1.0, 1.0), 1.0, 1e-14);
  EXPECT_NEAR(betaFunction(2.0, 3.0), 1.0 / 12.0, 1e-14 / 12.0);  // 1! 2! / 4!
  EXPECT_NEAR(betaFunction(0.5, 0.5), Pi, 1e-14 * Pi);
  // Large arguments: no overflow, ln B from std::lgamma.
  const double expected = std::exp(std::lgamma(1e5) + std::lgamma(3.5) - std::lgamma(1e5 + 3.5));
  EXPECT_NEAR(betaFunction(1e5, 3.5), expected, 1e-9 * expected);
}

// d/dx ln Gamma = digamma; d/da B(a, b) = B (psi(a) - psi(a + b)): central differences of
// std::lgamma stand in for psi.
TEST(SpecialFunctions, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 2>;
  const double h = 1e-6;
  for (const double x : {0.2, 1.0, 2.5, 11.0, 300.0}) {
    const Jet value = logGamma(Jet(x, 0));
    EXPECT_NEAR(value.a, std::lgamma(x), 1e-14 * std::max(1.0, std::abs(value.a)));
    EXPECT_NEAR(value.v[0], (std::lgamma(x + h) - std::lgamma(x - h)) / (2 * h),
                1e-7 * std::max(1.0, std::abs(value.v[0])));
  }
  const Jet a(1.7, 0), b(4.2, 1);
  const Jet beta = betaFunction(a, b);
  const auto betaDouble = [](double x, double y) {
    return std::exp(std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y));
  };
  EXPECT_NEAR(beta.v[0], (betaDouble(1.7 + h, 4.2) - betaDouble(1.7 - h, 4.2)) / (2 * h), 1e-8);
  EXPECT_NEAR(beta.v[1], (betaDouble(1.7, 4.2 + h) - betaDouble(1.7, 4.2 - h)) / (2 * h), 1e-8);
}

TEST(InverseErrorFunction, ErfOfErfinvIsIdentity) {
  // A few ulps: erf itself rounds, and |z| > 1/2 is solved through erfc(y) = 1 - |z|.
  for (double z = -0.999; z < 1.0; z += 0.001) EXPECT_NEAR(std::erf(erfinv(z)), z, 1e-15) << "z " << z;
  for (const double z : {1e-300, 1e-12, -1e-12}) EXPECT_NEAR(erfinv(z) / z, SqrtPi / 2.0, 1e-15);
}

TEST(InverseErrorFunction, InverseErfcKeepsRelativePrecisionInTheTails) {
  for (double q = 1e-300; q < 1.0; q *= 7.3) {
    const double y = inverseErfc(q);
    // The root lies within 1e-14 relative of y: erfc brackets q there. (Compared through y,
    // because erfc(y) / q amplifies one ulp of y by 2 y^2 ~ 1400 at q = 1e-300.)
    EXPECT_GT(std::erfc(y * (1.0 - 1e-14)), q) << "q " << q;
    EXPECT_LT(std::erfc(y * (1.0 + 1e-14)), q) << "q " << q;
    // erfc(-y) = 2 - erfc(y); 2 - q rounds, so the mirrored argument is the representable one.
    const double mirrored = 2.0 - q;
    EXPECT_NEAR(inverseErfc(mirrored), -inverseErfc(2.0 - mirrored), 1e-15 * y);
  }
  EXPECT_EQ(inverseErfc(1.0), 0.0);
  EXPECT_TRUE(std::isfinite(inverseErfc(0.0)));
  EXPECT_TRUE(std::isfinite(inverseErfc(2.0)));
}

}  // namespace special_functions_test
}  // namespace scatterlab
