// Rays and where a new ray may start on a surface without finding that surface again.
//
// Geometry is double precision throughout (docs/design.md, "Rules for kernel code": geometry
// that no parameter touches stays in double): a unit sphere seen from 4 units away is intersected to ~1e-15,
// so a fixed relative offset of 1e-9 along the normal clears the surface with six orders of magnitude to
// spare, and is still far below anything visible (a pixel of the peers' scene is ~1e-2 wide).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "materials/core/math.h"

namespace scatterlab {

struct Ray {
  Vec3d origin;
  Vec3d direction;  // unit length

  Vec3d at(double t) const { return origin + t * direction; }
};

inline constexpr double Infinity = std::numeric_limits<double>::infinity();

// Relative size of the offset (header comment).
inline constexpr double RayOffsetScale = 1e-9;

// A point just off the surface at p (normal n) on the side that `direction` leaves toward.
inline Vec3d offsetRayOrigin(const Vec3d& p, const Vec3d& n, const Vec3d& direction) {
  const double magnitude = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const double offset = RayOffsetScale * magnitude;
  return glm::dot(n, direction) >= 0 ? p + offset * n : p - offset * n;
}

inline Ray spawnRay(const Vec3d& p, const Vec3d& n, const Vec3d& direction) {
  return {offsetRayOrigin(p, n, direction), direction};
}

}  // namespace scatterlab
