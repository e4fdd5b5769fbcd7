#include "integrator/camera.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace scatterlab {

PinholeCamera::PinholeCamera(const Transform& cameraToWorld, double fovDegrees, int width, int height)
    : fovDegrees_(fovDegrees), width_(width), height_(height) {
  if (!(fovDegrees > 0 && fovDegrees < 180))
    throw std::invalid_argument("PinholeCamera: field of view " + std::to_string(fovDegrees) +
                                " not in (0, 180)");
  if (width < 1 || height < 1)
    throw std::invalid_argument("PinholeCamera: film must be at least 1 x 1 pixels");
  eye_ = cameraToWorld.point(Vec3d(0.0));
  forward_ = glm::normalize(cameraToWorld.vector(Vec3d(0, 0, -1)));
  right_ = glm::normalize(cameraToWorld.vector(Vec3d(1, 0, 0)));
  up_ = glm::normalize(cameraToWorld.vector(Vec3d(0, 1, 0)));
  pixelScale_ = std::tan(radians(fovDegrees) / 2.0) / double(std::max(width, height));
}

PinholeCamera PinholeCamera::lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up, double fovDegrees,
                                    int width, int height) {
  const Vec3d forward = target - eye;
  if (!(glm::length(forward) > 0)) throw std::invalid_argument("PinholeCamera: eye and target coincide");
  if (!(glm::length(glm::cross(glm::normalize(forward), glm::normalize(up))) > 1e-9))
    throw std::invalid_argument("PinholeCamera: up is parallel to the view direction");
  return PinholeCamera(Transform::cameraLookAt(eye, target, up), fovDegrees, width, height);
}

}  // namespace scatterlab
