#include <gtest/gtest.h>

#include "materials/bssrdf/burley.h"

namespace scatterlab {
namespace burley_test {

TEST(BurleyProfile, InverseCdfRoundTripsTo1e10) {
  // docs/validation.md section 6: F(r(u)) = u to 1e-10 for the exact closed-form inverse.
  for (const double d : {0.05, 1.0, 7.0}) {
    double worst = 0.0;
    for (int k = 0; k <= 100000; ++k) {
      const double u = k == 100000 ? 1.0 - 1e-12 : k / 100000.0;
      const double r = burleySampleRadius(d, u);
      worst = std::max(worst, std::abs(burleyCumulative(1.0, d, r) - u));
    }
    EXPECT_LT(worst, 1e-10) << d;
  }
}

TEST(BurleyProfile, ForwardThenInverseIsTheIdentity) {
  for (const double r : {1e-6, 1e-3, 0.1, 1.0, 5.0, 40.0})
    EXPECT_NEAR(burleySampleRadius(1.0, burleyCumulative(1.0, 1.0, r)), r, 1e-6 * r) << r;
  EXPECT_EQ(burleySampleRadius(1.0, 0.0), 0.0);
}

TEST(BurleyProfile, RadiusPdfIsTwoPiRTimesTheProfileOverA) {
  const double A = 0.6, d = 0.7;
  for (const double r : {1e-4, 0.1, 1.0, 3.0}) {
    EXPECT_NEAR(burleyRadiusPdf(d, r), 2 * Pi * r * burleyProfile(A, d, r) / A, 1e-14) << r;
    const double h = 1e-6;
    EXPECT_NEAR((burleyCumulative(1.0, d, r + h) - burleyCumulative(1.0, d, r - h)) / (2 * h),
                burleyRadiusPdf(d, r), 1e-8)
        << r;
  }
}

TEST(BurleyProfile, ShapeFactorFitsOfThePaper) {
  // Christensen & Burley 2015, section 5: values at A = 0.8 and A = 0.33, where each fit's
  // extra term vanishes.
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::Searchlight, 0.8), 1.05, 1e-15);
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::DiffuseTransmission, 0.8), 1.1, 1e-15);
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::SearchlightDiffuseMfp, 0.33), 3.5, 1e-15);
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::Searchlight, 0.2), 1.85 - 0.2 + 7 * 0.216, 1e-14);
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::DiffuseTransmission, 0.2), 1.9 - 0.2 + 3.5 * 0.36, 1e-14);
  EXPECT_NEAR(burleyShapeFactor(BurleyFit::SearchlightDiffuseMfp, 0.83), 3.5 + 100 * 0.0625, 1e-13);
}

TEST(BurleyProfile, FiniteAtZeroRadius) {
  const BurleyProfile p(Rgb(0.5), Rgb(1.0));
  EXPECT_TRUE(std::isfinite(p.eval(0.0).x));
  EXPECT_GT(p.eval(0.0).x, p.eval(1e-6).x);
  EXPECT_DOUBLE_EQ(p.radiusPdf(0, 0.0), 0.5);  // 2 / (4 d)
  EXPECT_THROW(BurleyProfile(Rgb(1.2), Rgb(1.0)), std::invalid_argument);
  EXPECT_THROW(BurleyProfile(Rgb(0.5), Rgb(0.0)), std::invalid_argument);
}

}  // namespace burley_test
}  // namespace scatterlab
