#include <gtest/gtest.h>

#include <cmath>

#include "materials/bsdf/diffuse_fresnel.h"
#include "materials/bsdf/fresnel_moments.h"

namespace scatterlab {
namespace fresnel_moments_test {

// pbrt-v3's 5th-order fits of the first two moments (src/core/bssrdf.cpp), for light arriving
// from the side of index eta: our fresnelMoment(k, 1 / eta). Fits, so agreement is to ~2e-3.
double pbrtMoment1(double eta) {
  const double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
  if (eta < 1) return 0.45966 - 1.73965 * eta + 3.37668 * e2 - 3.904945 * e3 + 2.49277 * e4 - 0.68441 * e5;
  return -4.61686 + 11.1136 * eta - 10.4646 * e2 + 5.11455 * e3 - 1.27198 * e4 + 0.12746 * e5;
}
double pbrtMoment2(double eta) {
  const double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
  if (eta < 1) return 0.27614 - 0.87350 * eta + 1.12077 * e2 - 0.65095 * e3 + 0.07883 * e4 + 0.04860 * e5;
  const double r = 1 / eta, r2 = r * r, r3 = r2 * r;
  return -547.033 + 45.3087 * r3 - 218.725 * r2 + 458.843 * r + 404.557 * eta - 189.519 * e2 + 54.9327 * e3 -
         9.00603 * e4 + 0.63942 * e5;
}

TEST(FresnelMoments, AgreeWithPbrtsPolynomialFits) {
  for (const double eta : {0.7, 0.8, 1.1, 1.3, 1.33, 1.5, 2.0}) {
    SCOPED_TRACE(eta);
    EXPECT_NEAR(fresnelMoment(1, 1.0 / eta), pbrtMoment1(eta), 2e-3);
    EXPECT_NEAR(fresnelMoment(2, 1.0 / eta), pbrtMoment2(eta), 2e-3);
  }
}

TEST(FresnelMoments, VanishForAnIndexMatchedInterface) {
  // F = 0 at eta = 1, except that fresnelDielectric's cos_t = sqrt(1 - (1 - mu^2)) rounds to 0
  // below mu ~ 1e-8 (grazing), where it then reflects fully: a sliver of ~5e-9.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(fresnelMoment(k, 1.0), 0.0, 1e-8);
}

// Etendue: the diffuse transmittances from the two sides satisfy
// 1 - 2 FM1(eta) = eta^2 (1 - 2 FM1(1 / eta)), an identity of the exact Fresnel terms.
TEST(FresnelMoments, FirstMomentsOfBothSidesObeyTheEtendueRelation) {
  for (const double eta : {1.1, 1.3, 1.5, 2.4}) {
    EXPECT_NEAR(1.0 - 2.0 * fresnelMoment(1, eta), eta * eta * (1.0 - 2.0 * fresnelMoment(1, 1.0 / eta)),
                1e-10)
        << eta;
    EXPECT_DOUBLE_EQ(diffuseFresnelReflectance(eta), 2.0 * fresnelMoment(1, eta));
  }
}

TEST(FresnelMoments, TotalInternalReflectionPartIsExact) {
  // From the dense side, every mu below the critical cosine reflects fully: FM_k >= mu_c^(k+1) / (k+1).
  const double eta = 1.0 / 1.5, criticalCos = std::sqrt(1.0 - eta * eta);
  for (int k = 0; k < 3; ++k) EXPECT_GT(fresnelMoment(k, eta), std::pow(criticalCos, k + 1) / (k + 1));
  EXPECT_THROW(fresnelMoment(1, 0.0), std::invalid_argument);
  EXPECT_THROW(fresnelMoment(-1, 1.5), std::invalid_argument);
}

}  // namespace fresnel_moments_test
}  // namespace scatterlab
