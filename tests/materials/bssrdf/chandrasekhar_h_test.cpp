#include <gtest/gtest.h>

#include <cmath>

#include "materials/bssrdf/chandrasekhar_h.h"
#include "materials/core/math.h"

namespace scatterlab {
namespace chandrasekhar_h_test {

// H is computed here, by the Gauss-Legendre iteration; these are its defining relations.
TEST(ChandrasekharH, ZerothMomentRelation) {
  // Integrating the H equation over mu gives integral_0^1 H = (2/c)(1 - sqrt(1 - c)): holds
  // once the iteration has converged.
  for (const double c : {0.3, 0.8, 0.99}) {
    const ChandrasekharH H(c);
    EXPECT_NEAR(H.moment(0), 2.0 / c * (1.0 - std::sqrt(1.0 - c)), 1e-13) << c;
  }
}

TEST(ChandrasekharH, SatisfiesTheAlternativeForm) {
  // 1 / H(mu) = sqrt(1 - c) + (c/2) integral_0^1 mu' H(mu') / (mu + mu') dmu' (Chandrasekhar
  // 1960, eq. V.(40)): a different equation H must also satisfy, here at off-node mu.
  for (const double c : {0.3, 0.8, 0.99}) {
    const ChandrasekharH H(c);
    for (const double mu : {0.05, 0.37, 1.0}) {
      double integral = 0.0;
      for (int j = 0; j < ChandrasekharH::NodeCount; ++j)
        integral += H.weights()[size_t(j)] * H.nodes()[size_t(j)] * H.values()[size_t(j)] /
                    (mu + H.nodes()[size_t(j)]);
      EXPECT_NEAR(1.0 / H(mu), std::sqrt(1.0 - c) + 0.5 * c * integral, 1e-9) << c << " " << mu;
    }
  }
}

TEST(ChandrasekharH, StartsAtOneAndGrowsWithMu) {
  const ChandrasekharH H(0.9);
  EXPECT_DOUBLE_EQ(H(0.0), 1.0);
  for (double mu = 0.1; mu <= 1.0; mu += 0.1) EXPECT_GT(H(mu), H(mu - 0.1));
  // No scattering: nothing is reflected.
  EXPECT_DOUBLE_EQ(ChandrasekharH(0.0).directionalAlbedo(1.0), 0.0);
}

TEST(ChandrasekharH, ReciprocalBrdfWithTheDirectionalAlbedo) {
  // R(mu0) = 2 pi integral_0^1 f(mu0, mu) mu dmu for the H-function BRDF.
  const ChandrasekharH H(0.8);
  double integral = 0.0;
  for (int j = 0; j < ChandrasekharH::NodeCount; ++j)
    integral += H.weights()[size_t(j)] * H.brdf(0.6, H.nodes()[size_t(j)]) * H.nodes()[size_t(j)];
  EXPECT_NEAR(2 * Pi * integral, H.directionalAlbedo(0.6), 1e-9);
  EXPECT_DOUBLE_EQ(H.brdf(0.3, 0.7), H.brdf(0.7, 0.3));
}

TEST(ChandrasekharH, SearchlightAlbedoInvertsTheDirectionalAlbedo) {
  // Burley's A range of the searchlight fit, A in [0.1, 0.99]. c is found to 1e-12; the
  // reflectance then to dR/dc * 1e-12 = H(1) / (2 sqrt(1 - c)) * 1e-12 ~ 4e-10 at A = 0.99.
  for (const double A : {0.1, 0.5, 0.9, 0.99}) {
    const double c = searchlightAlbedoForReflectance(A);
    EXPECT_NEAR(ChandrasekharH(c).directionalAlbedo(1.0), A, 1e-9) << A;
  }
  EXPECT_THROW(searchlightAlbedoForReflectance(1.0), std::invalid_argument);
}

}  // namespace chandrasekhar_h_test
}  // namespace scatterlab
