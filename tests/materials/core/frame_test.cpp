#include <gtest/gtest.h>

#include "materials/core/frame.h"
#include "materials/core/spherical.h"
#include "materials/core/warp.h"

namespace scatterlab {
namespace frame_test {

void expectOrthonormal(const Framed& f) {
  EXPECT_NEAR(glm::length(f.s), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(f.t), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(f.n), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(f.s, f.t), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(f.s, f.n), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(f.t, f.n), 0.0, 1e-12);
  // Right-handed: s x t = n, so local z is the normal.
  const Vec3d c = glm::cross(f.s, f.t);
  EXPECT_NEAR(glm::length(c - f.n), 0.0, 1e-12);
}

TEST(Frame, FromNormalIsOrthonormalEverywhere) {
  for (int i = 0; i < 200; ++i) {
    const Vec3d n = sampleUniformSphere({(i + 0.5) / 200.0, std::fmod(i * 0.618034, 1.0)});
    expectOrthonormal(Framed::fromNormal(n));
  }
  expectOrthonormal(Framed::fromNormal({0, 0, 1}));
  expectOrthonormal(Framed::fromNormal({0, 0, -1}));
}

TEST(Frame, ToLocalAndBackRoundTrip) {
  const Framed f = Framed::fromNormal(glm::normalize(Vec3d(0.3, -0.5, 0.8)));
  const Vec3d w = glm::normalize(Vec3d(-0.2, 0.7, 0.1));
  const Vec3d back = f.toWorld(f.toLocal(w));
  EXPECT_NEAR(glm::length(back - w), 0.0, 1e-14);
  EXPECT_NEAR(f.toLocal(f.n).z, 1.0, 1e-14);
}

TEST(Frame, TangentFollowsGivenTangent) {
  const Vec3d n(0, 0, 1);
  const Framed f = Framed::fromNormalTangent(n, glm::normalize(Vec3d(1, 1, 0.5)));
  expectOrthonormal(f);
  EXPECT_NEAR(glm::length(f.s - glm::normalize(Vec3d(1, 1, 0))), 0.0, 1e-12);
}

TEST(Spherical, TrigonometryOfDirections) {
  const Vec3d w = sphericalDirection(std::sin(0.7), std::cos(0.7), 2.0);
  EXPECT_NEAR(sphericalTheta(w), 0.7, 1e-14);
  EXPECT_NEAR(sphericalPhi(w), 2.0, 1e-14);
  EXPECT_NEAR(cosPhi(w), std::cos(2.0), 1e-14);
  EXPECT_NEAR(sinPhi(w), std::sin(2.0), 1e-14);
  EXPECT_NEAR(tan2Theta(w), sqr(std::tan(0.7)), 1e-12);
  // The pole has no phi: (1, 0) by convention, never NaN.
  EXPECT_EQ(cosPhi(Vec3d(0, 0, 1)), 1.0);
  EXPECT_EQ(sinPhi(Vec3d(0, 0, 1)), 0.0);
}

TEST(Spherical, SafeFunctionsClampRoundOff) {
  EXPECT_EQ(safeSqrt(-1e-17), 0.0);
  EXPECT_EQ(safeAcos(1.0 + 1e-15), 0.0);
  EXPECT_NEAR(safeAcos(-1.0 - 1e-15), Pi, 1e-15);
  EXPECT_NEAR(safeAsin(1.0 + 1e-15), PiOver2, 1e-15);
}

TEST(Spherical, ReflectMirrorsAboutNormal) {
  const Vec3d w = glm::normalize(Vec3d(0.3, 0.4, 0.5));
  const Vec3d r = reflect(w, Vec3d(0, 0, 1));
  EXPECT_NEAR(r.x, -w.x, 1e-15);
  EXPECT_NEAR(r.y, -w.y, 1e-15);
  EXPECT_NEAR(r.z, w.z, 1e-15);
}

}  // namespace frame_test
}  // namespace scatterlab
