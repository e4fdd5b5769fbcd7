// A pinhole camera: rays from one point through a film of width x height pixels.
//
// Film coordinates are in pixels, (0, 0) at the top-left corner of the image, x to the right,
// y down; pixel (i, j) covers [i, i + 1) x [j, j + 1). The field of view spans the larger image
// dimension (Blender's sensor fit "auto", which the peers' Cycles scene uses), so for a square
// image the film point (x, y) looks along
//   forward + tan(fov / 2) (2 x / s - w / s) right - tan(fov / 2) (2 y / s - h / s) up,
// s = max(w, h), exactly the rays peers/exr_stats.py assumes for its pixel masks.
//
// Light tracing and BDPT need the camera from the other side: where on the film a direction
// from the eye lands (filmPoint), and the camera's importance. A pixel's value is the mean of
// L over its square of film (box filter), so a film point's importance per unit solid angle is
// dA_film / d omega = 1 / (a cos^3 theta), a = pixelAngle()^2 the pixel's area on the plane at
// unit distance and theta the angle to the view axis (a plane at unit distance along the axis
// is 1 / cos theta away and tilted by theta). Camera rays are spread evenly over the film, so
// the density of their directions is 1 / (a W H cos^3 theta) (directionPdf), the
// pinhole's importance as pbrt-v4's PerspectiveCamera::We and PDF_We have it (Pharr, Jakob &
// Humphreys, 4th ed., sec. 5.4.1).
#pragma once

#include <optional>

#include "integrator/ray.h"
#include "integrator/transform.h"

namespace scatterlab {

// Where a direction from the eye meets the film.
struct FilmPoint {
  Vec2d position;   // pixels, as generateRay takes them
  double cosTheta;  // to the view axis, > 0
};

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

  // The film point a unit direction `w` from the eye passes through, or nothing when it points
  // behind the camera or outside the film widened by `margin` pixels on every side.
  std::optional<FilmPoint> filmPoint(const Vec3d& w, double margin = 0.0) const {
    const double cosTheta = glm::dot(w, forward_);
    if (!(cosTheta > 0)) return std::nullopt;
    const double x = glm::dot(w, right_) / cosTheta, y = glm::dot(w, up_) / cosTheta;
    const Vec2d film((x / pixelScale_ + width_) / 2.0, (height_ - y / pixelScale_) / 2.0);
    if (!(film.x >= -margin && film.x < width_ + margin && film.y >= -margin && film.y < height_ + margin))
      return std::nullopt;
    return FilmPoint{film, cosTheta};
  }
  // The importance of one pixel toward a film point at cos theta, per unit solid angle:
  // 1 / (a cos^3 theta) (header comment).
  double pixelImportance(double cosTheta) const {
    return 1.0 / (pixelAngle() * pixelAngle() * cosTheta * cosTheta * cosTheta);
  }
  // The density per unit solid angle of camera ray directions (uniform over the film) at
  // cos theta: pixelImportance / (W H).
  double directionPdf(double cosTheta) const {
    return pixelImportance(cosTheta) / (double(width_) * height_);
  }

 private:
  Vec3d eye_{0.0}, forward_{0, 0, -1}, right_{1, 0, 0}, up_{0, 1, 0};
  double fovDegrees_ = 45.0;
  int width_ = 1, height_ = 1;
  double pixelScale_ = 1.0;  // tan(fov / 2) / max(width, height)
};

}  // namespace scatterlab
