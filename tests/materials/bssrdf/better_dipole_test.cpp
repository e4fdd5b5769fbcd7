#include <gtest/gtest.h>

#include "materials/bsdf/fresnel_moments.h"
#include "materials/bssrdf/better_dipole.h"

namespace scatterlab {
namespace better_dipole_test {

TEST(BetterDipole, ANonAbsorbingMediumReflectsEverything) {
  // alpha' = 1: sigma_tr = 0 and Rd = C_E + 2 A C_phi = 1 exactly, at any eta.
  for (const double eta : {1.0, 1.3, 1.5, 2.0}) {
    const BetterDipole<double> d = makeBetterDipole(2.0, 0.0, fresnelBoundary(eta));
    EXPECT_NEAR(betterDipoleTotal(d), 1.0, 1e-14) << eta;
  }
}

TEST(BetterDipole, BoundaryConstantsFromTheFresnelMoments) {
  const FresnelBoundary matched = fresnelBoundary(1.0);
  EXPECT_NEAR(matched.A, 1.0, 1e-14);
  EXPECT_NEAR(matched.cPhi, 0.25, 1e-14);
  EXPECT_NEAR(matched.cE, 0.5, 1e-14);
  const FresnelBoundary b = fresnelBoundary(1.3);
  const double c1 = fresnelMoment(1, 1 / 1.3), c2 = fresnelMoment(2, 1 / 1.3);
  EXPECT_DOUBLE_EQ(b.A, (1 + 3 * c2) / (1 - 2 * c1));
}

TEST(BetterDipole, ClosedFormIsTheLimitOfTheCumulative) {
  for (const double sigmaA : {0.0001, 0.01, 0.5}) {
    const BetterDipole<double> d = makeBetterDipole(1.0, sigmaA, fresnelBoundary(1.4));
    EXPECT_NEAR(betterDipoleCumulative(d, 1e7), betterDipoleTotal(d), 1e-9) << sigmaA;
  }
}

TEST(BetterDipole, ContinuousAsAbsorptionVanishes) {
  // The closed form's (1 - e^(-sigma_tr 4AD)) / sigma_tr term has a finite limit at sigma_tr = 0.
  const FresnelBoundary b = fresnelBoundary(1.3);
  const double atZero = betterDipoleTotal(makeBetterDipole(1.0, 0.0, b));
  const double nearZero = betterDipoleTotal(makeBetterDipole(1.0, 1e-12, b));
  EXPECT_NEAR(nearZero, atZero, 1e-5);
  EXPECT_LT(nearZero, atZero);
}

TEST(BetterDipole, ProfileIsPositiveAndDecreasing) {
  const BetterDipole<double> d = makeBetterDipole(0.9, 0.05, fresnelBoundary(1.3));
  double previous = INFINITY;
  for (double r = 0.0; r < 60.0; r += 0.25) {
    const double R = betterDipoleProfile(d, r);
    EXPECT_GT(R, 0.0) << r;
    EXPECT_LT(R, previous) << r;
    previous = R;
  }
}

}  // namespace better_dipole_test
}  // namespace scatterlab
