#include <gtest/gtest.h>

#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/separable_bssrdf.h"
#include "materials/core/quadrature.h"

namespace scatterlab {
namespace separable_bssrdf_test {

// The directional term's normalisation c, proven: integral over the hemisphere of
// Ft(w) |cos| / (pi c) dw = 1, by adaptive quadrature of the exact Fresnel term (not by the
// moment the code computes c from).
TEST(SeparableBssrdf, DirectionalTermIntegratesToOne) {
  for (const double eta : {0.8, 1.0, 1.3, 1.5, 2.0}) {
    const double c = separableNormalization(eta);
    QuadratureOptions q;
    q.relativeTolerance = 1e-12;
    q.absoluteTolerance = 1e-15;
    q.minDepth = 6;
    const double integral = adaptiveSimpson2D(
        [&](double cosTheta, double) { return separableDirectional(cosTheta, eta, c) * cosTheta; }, 0.0, 1.0,
        -Pi, Pi, q);
    EXPECT_NEAR(integral, 1.0, 1e-9) << eta;
  }
}

TEST(SeparableBssrdf, NormalisationMatchesPbrtsFit) {
  // pbrt-v3: c = 1 - 2 FresnelMoment1(1 / eta) with its polynomial fit (eta < 1 branch).
  for (const double eta : {1.3, 1.5}) {
    const double x = 1 / eta, x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
    const double fit = 0.45966 - 1.73965 * x + 3.37668 * x2 - 3.904945 * x3 + 2.49277 * x4 - 0.68441 * x5;
    EXPECT_NEAR(separableNormalization(eta), 1 - 2 * fit, 4e-3) << eta;
  }
  EXPECT_DOUBLE_EQ(separableNormalization(1.0), 1.0);
}

TEST(SeparableBssrdf, IsFresnelTransmittanceTimesProfileTimesFresnelTransmittance) {
  const auto profile = std::make_shared<BurleyProfile>(Rgb(0.4, 0.5, 0.6), Rgb(1.0, 2.0, 3.0));
  const SeparableBssrdf s(profile, 1.4);
  const double cosI = 0.7, cosO = 0.3, r = 0.8;
  const Rgb expected = (1 - fresnelDielectric(cosI, 1.4)) * (1 - fresnelDielectric(cosO, 1.4)) *
                       profile->eval(r) / (Pi * s.normalization());
  const Rgb got = s.eval(r, cosI, cosO);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-15 * expected[c]);
  EXPECT_EQ(s.eval(r, -0.5, cosO), Rgb(0.0));
  EXPECT_EQ(s.directional(-0.1), 0.0);
}

}  // namespace separable_bssrdf_test
}  // namespace scatterlab
