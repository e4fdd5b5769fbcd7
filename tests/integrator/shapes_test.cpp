// Ray-sphere and ray-plane intersection: hits from outside and inside, misses, tangents,
// precision for small far spheres, and that a spawned ray never finds its own surface again.
#include <gtest/gtest.h>

#include "integrator/shapes.h"
#include "materials/core/frame.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"

namespace scatterlab {
namespace shapes_test {

TEST(Sphere, HitsFromOutsideAtTheNearRoot) {
  const Sphere sphere{Vec3d(0.0), 1.0};
  const Ray ray{Vec3d(0, -4, 0), Vec3d(0, 1, 0)};
  EXPECT_DOUBLE_EQ(sphere.intersect(ray, 0.0, Infinity), 3.0);
  // With the near root excluded by tMax, nothing closer than tMax is reported.
  EXPECT_EQ(sphere.intersect(ray, 0.0, 2.5), Infinity);
  // Past the near root, the far one.
  EXPECT_DOUBLE_EQ(sphere.intersect(ray, 3.5, Infinity), 5.0);
}

TEST(Sphere, HitsFromInsideAtTheFarRoot) {
  const Sphere sphere{Vec3d(1, 2, 3), 2.0};
  const Ray ray{Vec3d(1, 2, 3), glm::normalize(Vec3d(1, 1, 0))};
  EXPECT_NEAR(sphere.intersect(ray, 0.0, Infinity), 2.0, 1e-15);
}

TEST(Sphere, MissesAndGrazes) {
  const Sphere sphere{Vec3d(0.0), 1.0};
  EXPECT_EQ(sphere.intersect({Vec3d(0, -4, 1.0000001), Vec3d(0, 1, 0)}, 0.0, Infinity), Infinity);
  EXPECT_NEAR(sphere.intersect({Vec3d(0, -4, 0.9999999), Vec3d(0, 1, 0)}, 0.0, Infinity), 4.0, 1e-3);
  EXPECT_EQ(sphere.intersect({Vec3d(0, -4, 0), Vec3d(0, -1, 0)}, 0.0, Infinity), Infinity);  // behind
}

TEST(Sphere, SmallFarSphereKeepsItsPrecision) {
  // b^2 - c would cancel every digit here; the perpendicular form keeps them (Haines et al. 2019).
  const Sphere sphere{Vec3d(0, 1e6, 0), 1e-3};
  const double t = sphere.intersect({Vec3d(0.0), Vec3d(0, 1, 0)}, 0.0, Infinity);
  EXPECT_NEAR(t, 1e6 - 1e-3, 1e-9);
}

TEST(Sphere, GeometryHasOutwardNormalAndTangentAroundTheAxis) {
  const Sphere sphere{Vec3d(0.0), 2.0, Vec3d(0, 0, 1)};
  const SurfaceGeometry g = sphere.geometryAt(Vec3d(2, 0, 0));
  EXPECT_NEAR(glm::length(g.normal - Vec3d(1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(g.tangent - Vec3d(0, 1, 0)), 0.0, 1e-15);  // d p / d phi
  // At the pole there is no tangent; the caller picks any frame.
  EXPECT_EQ(sphere.geometryAt(Vec3d(0, 0, 2)).tangent, Vec3d(0.0));
  const Vec2d uv = sphere.uvAt(Vec3d(0, 0, -2));
  EXPECT_NEAR(uv.y, 1.0, 1e-12);
}

TEST(Plane, HitsFromEitherSideAndNotWhenParallel) {
  const Plane plane{Vec3d(0, 0, -1), Vec3d(0, 0, 1), Vec3d(1, 0, 0)};
  EXPECT_DOUBLE_EQ(plane.intersect({Vec3d(0, 0, 1), Vec3d(0, 0, -1)}, 0.0, Infinity), 2.0);
  EXPECT_DOUBLE_EQ(plane.intersect({Vec3d(0, 0, -3), Vec3d(0, 0, 1)}, 0.0, Infinity), 2.0);
  EXPECT_EQ(plane.intersect({Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, 0.0, Infinity), Infinity);
  const Vec2d uv = plane.uvAt(Vec3d(2, 3, -1));
  EXPECT_DOUBLE_EQ(uv.x, 2.0);
  EXPECT_DOUBLE_EQ(uv.y, 3.0);
}

// Rays spawned from random points of a sphere, in random directions on either side, never hit
// the surface they start on within the offset; those leaving inward meet the far side.
TEST(SpawnRay, NeverFindsItsOwnSurface) {
  const Sphere sphere{Vec3d(0.3, -0.2, 0.1), 1.0};
  CounterRng rng(3, 0);
  int inward = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3d n = sampleUniformSphere(rng.uniform2D());
    const Vec3d p = sphere.center + n * sphere.radius;
    const Vec3d w = sampleUniformSphere(rng.uniform2D());
    const Ray ray = spawnRay(p, n, w);
    const double t = sphere.intersect(ray, 0.0, Infinity);
    if (glm::dot(w, n) > 0) {
      EXPECT_EQ(t, Infinity) << "outward ray " << i << " hit its own sphere at t = " << t;
    } else {
      ++inward;
      // The chord from p along w: length -2 (w.n) r, from a start RayOffsetScale |p| inside,
      // which shortens it by about offset / |w.n| (the chord's slope in the depth).
      const double cosine = -glm::dot(w, n);
      const double offset = RayOffsetScale * std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      EXPECT_NEAR(t, 2.0 * cosine * sphere.radius, 2.0 * offset / cosine + 1e-13) << "inward ray " << i;
    }
  }
  EXPECT_GT(inward, 9000);
}

// A ray trapped in a sphere by total internal reflection (the "whispering gallery" of grazing
// entries into glass) bounces hundreds of times; each bounce starts from the last hit, so the
// hits must stay on the surface instead of drifting off it by a growing error.
TEST(SpawnRay, InternalReflectionsStayOnTheSphere) {
  const Sphere sphere{Vec3d(0.1, 0.2, -0.3), 1.0};
  Ray ray{sphere.center, glm::normalize(Vec3d(0.3, 1.0, 0.2))};
  ray.origin = sphere.center + glm::normalize(Vec3d(1.0, -0.2, 0.4)) * 0.999;  // near the wall
  ray.direction = glm::normalize(glm::cross(ray.origin - sphere.center, Vec3d(0, 0, 1)) +
                                 0.6 * (sphere.center - ray.origin));
  for (int bounce = 0; bounce < 1000; ++bounce) {
    const double t = sphere.intersect(ray, 0.0, Infinity);
    ASSERT_LT(t, Infinity) << "escaped at bounce " << bounce;
    const Vec3d p = ray.at(t);
    ASSERT_NEAR(glm::length(p - sphere.center), 1.0, 1e-12) << "bounce " << bounce;
    const SurfaceGeometry g = sphere.geometryAt(p);
    const Framed frame(g.tangent, glm::cross(g.normal, g.tangent), g.normal);
    const Vec3d local = frame.toLocal(-ray.direction);
    ray = spawnRay(p, g.normal, frame.toWorld(Vec3d(-local.x, -local.y, local.z)));  // mirror, inward
  }
}

}  // namespace shapes_test
}  // namespace scatterlab
