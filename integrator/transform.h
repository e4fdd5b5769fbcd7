// Affine transforms of points, vectors and normals (a 4x4 matrix and its inverse, on GLM), for
// placing the camera (look-at), rotating the environment and placing shapes.
#pragma once

#include <cmath>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "materials/core/math.h"

namespace scatterlab {

class Transform {
 public:
  Transform() = default;
  explicit Transform(const glm::dmat4& matrix) : matrix_(matrix), inverse_(glm::inverse(matrix)) {}

  static Transform translate(const Vec3d& offset) {
    return Transform(glm::translate(glm::dmat4(1.0), offset));
  }
  static Transform rotate(double degrees, const Vec3d& axis) {
    return Transform(glm::rotate(glm::dmat4(1.0), radians(degrees), glm::normalize(axis)));
  }
  static Transform scale(double factor) { return Transform(glm::scale(glm::dmat4(1.0), Vec3d(factor))); }
  // Camera to world for a camera at `eye` looking at `target` with `up` as the image's up:
  // the camera looks down its -z axis with +y up and +x to the right (glm::lookAt's view
  // matrix, inverted). eye != target and up not parallel to the view direction.
  static Transform cameraLookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up) {
    return Transform(glm::inverse(glm::lookAt(eye, target, up)));
  }

  Transform operator*(const Transform& other) const {
    return Transform(matrix_ * other.matrix_, other.inverse_ * inverse_);
  }
  Transform inverse() const { return Transform(inverse_, matrix_); }

  Vec3d point(const Vec3d& p) const { return Vec3d(matrix_ * glm::dvec4(p, 1.0)); }
  Vec3d vector(const Vec3d& v) const { return Vec3d(matrix_ * glm::dvec4(v, 0.0)); }
  // Normals transform by the inverse transpose, so they stay orthogonal to tangent vectors.
  Vec3d normal(const Vec3d& n) const { return Vec3d(glm::transpose(inverse_) * glm::dvec4(n, 0.0)); }

  const glm::dmat4& matrix() const { return matrix_; }
  // The linear part (rotation, scale) as a 3x3 matrix.
  glm::dmat3 linear() const { return glm::dmat3(matrix_); }

  // The uniform scale factor when the transform is a similarity (rotation, uniform scale and
  // translation, no shear, no mirror), within `tolerance`; nothing otherwise. Spheres may only
  // be placed by similarities: anything else would make them ellipsoids.
  std::optional<double> uniformScale(double tolerance = 1e-9) const {
    const glm::dmat3 a = linear();
    const double s = std::cbrt(glm::determinant(a));
    if (!(s > 0)) return std::nullopt;
    const glm::dmat3 gram = glm::transpose(a) * a / (s * s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)) > tolerance) return std::nullopt;
    return s;
  }

 private:
  Transform(const glm::dmat4& matrix, const glm::dmat4& inverse) : matrix_(matrix), inverse_(inverse) {}

  glm::dmat4 matrix_{1.0}, inverse_{1.0};
};

}  // namespace scatterlab
