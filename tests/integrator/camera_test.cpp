// The pinhole camera: the peers' framing (exr_stats.py's ray formula), orientation (+X to the
// right, +Z up for a camera on -Y), field of view, and transforms.
#include <gtest/gtest.h>

#include "integrator/camera.h"
#include "integrator/scene_presets.h"

namespace scatterlab {
namespace camera_test {

TEST(PinholeCamera, MatchesThePeersRayFormula) {
  // exr_stats.py: pixel (i, j from the bottom) of a W x H image looks along (X, 1, Y) with
  // X = (2 (i + 0.5) / s - W / s) t, Y = (2 (j + 0.5) / s - H / s) t, s = max(W, H), t = tan(fov / 2).
  const int w = 40, h = 30;
  const PinholeCamera camera = PinholeCamera::lookAt(Vec3d(0, -4, 0), Vec3d(0.0), Vec3d(0, 0, 1), 45.0, w, h);
  const double t = std::tan(radians(45.0) / 2.0), s = 40.0;
  for (int row = 0; row < h; row += 7)
    for (int i = 0; i < w; i += 9) {
      const int j = h - 1 - row;  // our rows run from the top
      const Vec3d expected =
          glm::normalize(Vec3d((2 * (i + 0.5) / s - w / s) * t, 1.0, (2 * (j + 0.5) / s - h / s) * t));
      const Ray ray = camera.generateRay(Vec2d(i + 0.5, row + 0.5));
      EXPECT_NEAR(glm::length(ray.direction - expected), 0.0, 1e-14) << "pixel " << i << ", " << row;
      EXPECT_NEAR(glm::length(ray.origin - Vec3d(0, -4, 0)), 0.0, 1e-14);
    }
}

TEST(PinholeCamera, LooksAtTheTargetWithUpAndRight) {
  const PinholeCamera camera =
      PinholeCamera::lookAt(Vec3d(1, 2, 3), Vec3d(1, 10, 3), Vec3d(0, 0, 1), 60.0, 10, 10);
  EXPECT_NEAR(glm::length(camera.forward() - Vec3d(0, 1, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(camera.right() - Vec3d(1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(camera.up() - Vec3d(0, 0, 1)), 0.0, 1e-15);
  // The left and right image edges are fov apart.
  const Vec3d left = camera.generateRay(Vec2d(0, 5)).direction,
              right = camera.generateRay(Vec2d(10, 5)).direction;
  EXPECT_NEAR(std::acos(glm::dot(left, right)), radians(60.0), 1e-12);
}

TEST(PinholeCamera, RejectsImpossibleSettings) {
  EXPECT_THROW(PinholeCamera::lookAt(Vec3d(0.0), Vec3d(0.0), Vec3d(0, 0, 1), 45, 8, 8),
               std::invalid_argument);
  EXPECT_THROW(PinholeCamera::lookAt(Vec3d(0.0), Vec3d(0, 0, 1), Vec3d(0, 0, 1), 45, 8, 8),
               std::invalid_argument);
  EXPECT_THROW(PinholeCamera::lookAt(Vec3d(0.0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), 180, 8, 8),
               std::invalid_argument);
  EXPECT_THROW(PinholeCamera::lookAt(Vec3d(0.0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), 45, 0, 8),
               std::invalid_argument);
}

TEST(Transform, ComposesInvertsAndTransformsNormals) {
  const Transform a =
      Transform::translate(Vec3d(1, 2, 3)) * Transform::rotate(90.0, Vec3d(0, 0, 1)) * Transform::scale(2.0);
  EXPECT_NEAR(glm::length(a.point(Vec3d(1, 0, 0)) - Vec3d(1, 4, 3)), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(a.inverse().point(a.point(Vec3d(0.3, -0.7, 2))) - Vec3d(0.3, -0.7, 2)), 0.0, 1e-14);
  EXPECT_NEAR(*a.uniformScale(), 2.0, 1e-12);
  // A shear keeps normals orthogonal to the tangent plane only through the inverse transpose.
  const Transform shear(glm::dmat4(1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
  const Vec3d tangent = shear.vector(Vec3d(1, 1, 0)), normal = shear.normal(Vec3d(1, -1, 0));
  EXPECT_NEAR(glm::dot(tangent, normal), 0.0, 1e-15);
  EXPECT_GT(std::abs(glm::dot(tangent, shear.vector(Vec3d(1, -1, 0)))), 0.1);  // as a vector it would tilt
  EXPECT_FALSE(shear.uniformScale());
  EXPECT_FALSE(Transform::scale(-1.0).uniformScale());  // a mirror
}

}  // namespace camera_test
}  // namespace scatterlab
