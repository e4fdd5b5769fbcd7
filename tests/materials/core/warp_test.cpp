// Round trips of every warp triplet: invert(sample(u)) == u, the sample lies in its domain,
// and the pdf is the one of the domain's measure. (Their chi-square tests against the pdf are
// in tests/validation/warp_chi_square_test.cpp.)
#include <gtest/gtest.h>

#include "materials/core/warp.h"

namespace scatterlab {
namespace warp_test {

// A grid of u that avoids the exact edges, where phi = 0 and 2 pi (or the disk's centre)
// are the same point and no inverse can return both.
std::vector<Vec2d> interiorGrid(int n = 37) {
  std::vector<Vec2d> us;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) us.emplace_back((i + 0.5) / n, (j + 0.5) / n);
  return us;
}

void expectRoundTrip(const Vec2d& u, const Vec2d& back, const char* warp) {
  EXPECT_NEAR(back.x, u.x, 1e-12) << warp << " u=(" << u.x << ", " << u.y << ")";
  EXPECT_NEAR(back.y, u.y, 1e-12) << warp << " u=(" << u.x << ", " << u.y << ")";
}

TEST(Warp, UniformSphereRoundTrip) {
  for (const Vec2d& u : interiorGrid()) {
    const Vec3d w = sampleUniformSphere(u);
    EXPECT_NEAR(glm::length(w), 1.0, 1e-14);
    expectRoundTrip(u, invertUniformSphere(w), "uniform sphere");
  }
  EXPECT_DOUBLE_EQ(uniformSpherePdf(), 1.0 / (4.0 * Pi));
}

TEST(Warp, UniformHemisphereRoundTrip) {
  for (const Vec2d& u : interiorGrid()) {
    const Vec3d w = sampleUniformHemisphere(u);
    EXPECT_GE(w.z, 0.0);
    EXPECT_NEAR(glm::length(w), 1.0, 1e-14);
    expectRoundTrip(u, invertUniformHemisphere(w), "uniform hemisphere");
  }
  EXPECT_DOUBLE_EQ(uniformHemispherePdf(), 1.0 / (2.0 * Pi));
}

TEST(Warp, ConcentricDiskRoundTrip) {
  for (const Vec2d& u : interiorGrid()) {
    const Vec2d p = sampleConcentricDisk(u);
    EXPECT_LE(glm::length(p), 1.0 + 1e-15);
    expectRoundTrip(u, invertConcentricDisk(p), "concentric disk");
  }
}

TEST(Warp, ConcentricDiskMapsSquareEdgesToCircle) {
  // Shirley-Chiu: the square's boundary maps onto the unit circle.
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    EXPECT_NEAR(glm::length(sampleConcentricDisk({t, 0.0})), 1.0, 1e-14);
    EXPECT_NEAR(glm::length(sampleConcentricDisk({1.0, t})), 1.0, 1e-14);
  }
}

TEST(Warp, CosineHemisphereRoundTripAndPdf) {
  for (const Vec2d& u : interiorGrid()) {
    const Vec3d w = sampleCosineHemisphere(u);
    EXPECT_GE(w.z, 0.0);
    EXPECT_NEAR(glm::length(w), 1.0, 1e-14);
    expectRoundTrip(u, invertCosineHemisphere(w), "cosine hemisphere");
  }
  EXPECT_DOUBLE_EQ(cosineHemispherePdf(0.5), 0.5 / Pi);
  EXPECT_EQ(cosineHemispherePdf(-0.1), 0.0);
}

TEST(Warp, UniformConeRoundTripAndSupport) {
  for (double cosMax : {-0.5, 0.0, 0.5, 0.99, 0.9999}) {
    for (const Vec2d& u : interiorGrid(19)) {
      const Vec3d w = sampleUniformCone(u, cosMax);
      EXPECT_GE(w.z, cosMax - 1e-15);
      EXPECT_NEAR(glm::length(w), 1.0, 1e-14);
      const Vec2d back = invertUniformCone(w, cosMax);
      // u0 passes through 1 - cos, which loses digits as the cone narrows.
      EXPECT_NEAR(back.x, u.x, 1e-12 / (1.0 - cosMax)) << "cosMax " << cosMax;
      EXPECT_NEAR(back.y, u.y, 1e-12);
    }
    EXPECT_DOUBLE_EQ(uniformConePdf(cosMax), 1.0 / (2.0 * Pi * (1.0 - cosMax)));
  }
}

}  // namespace warp_test
}  // namespace scatterlab
