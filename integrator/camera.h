// A pinhole camera: rays from one point through a film of width x height pixels.
//
// Film coordinates are in pixels, (0, 0) at the top-left corner of the image, x to the right,
// y down; pixel (i, j) covers [i, i + 1) x [j, j + 1). The field of view spans the larger image
// dimension (Blender's sensor fit "auto", which the peers' Cycles scene uses), so for a square
// image the film point (x, y) looks along
//   forward + tan(fov / 2) (2 x / s - w / s) right - tan(fov / 2) (2 y / s - h / s) up,
// s = max(w, h), exactly the rays peers/exr_stats.py assumes for its pixel masks.
#pragma once

#include "integrator/ray.h"
#include "integrator/transform.h"

namespace scatterlab {

class PinholeCamera {
 public:
  PinholeCamera() = default;
  // fovDegrees in (0, 180); width, height >= 1. std::invalid_argument otherwise.
  PinholeCamera(const Transform& cameraToWorld, double fovDegrees, int width, int height);
  // A camera at `eye` looking at `target`, `up` the image's up direction.
  static PinholeCamera lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up, double fovDegrees,
                              int width, int height);

  Ray generateRay(const Vec2d& film) const {
    const double x = (2.0 * film.x - width_) * pixelScale_;
    const double y = (height_ - 2.0 * film.y) * pixelScale_;
    return {eye_, glm::normalize(forward_ + x * right_ + y * up_)};
  }

  int width() const { return width_; }
  int height() const { return height_; }
  double fovDegrees() const { return fovDegrees_; }
  const Vec3d& eye() const { return eye_; }
  const Vec3d& forward() const { return forward_; }
  const Vec3d& right() const { return right_; }
  const Vec3d& up() const { return up_; }
  // The size of one pixel on the plane at unit distance along the view direction.
  double pixelAngle() const { return 2.0 * pixelScale_; }

 private:
  Vec3d eye_{0.0}, forward_{0, 0, -1}, right_{1, 0, 0}, up_{0, 1, 0};
  double fovDegrees_ = 45.0;
  int width_ = 1, height_ = 1;
  double pixelScale_ = 1.0;  // tan(fov / 2) / max(width, height)
};

}  // namespace scatterlab
