// The analytic shapes of a material-sphere scene: spheres and infinite planes. Each gives the
// nearest hit of a ray in (tMin, tMax) and the local geometry there: normal (outward for a
// sphere, the given side for a plane), tangent (the anisotropy axis of a model placed on it)
// and surface coordinates for textures.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "integrator/ray.h"
#include "materials/core/math.h"

namespace scatterlab {

// Where a ray meets a shape: what a material needs to be placed there. Texture coordinates
// are separate (uvAt), since only textured materials pay for them.
struct SurfaceGeometry {
  Vec3d normal;   // unit; also the shading normal (analytic shapes have exact normals)
  Vec3d tangent;  // unit, orthogonal to the normal (or zero where the shape has none: a pole)
};

struct Sphere {
  Vec3d center{0.0};
  double radius = 1.0;
  Vec3d axis{0, 0, 1};  // unit: the pole of the (theta, phi) coordinates; tangents circle it

  // The nearest t in (tMin, tMax) where ray meets the sphere, or Infinity. The discriminant
  // is computed from the ray's perpendicular distance to the centre rather than as b^2 - c,
  // which cancels catastrophically for small spheres far away (Haines, Guenther, Akenine-Moller,
  // "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7,
  // eq. 7.5-7.6), and the two roots as c / q and q (Press et al., Numerical Recipes, 5.6).
  double intersect(const Ray& ray, double tMin, double tMax) const {
    const Vec3d f = ray.origin - center;
    const double b = -glm::dot(f, ray.direction);
    const Vec3d perpendicular = f + b * ray.direction;
    const double discriminant = radius * radius - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0) return Infinity;
    const double c = glm::dot(f, f) - radius * radius;
    const double q = b + std::copysign(std::sqrt(discriminant), b);
    double t0 = q != 0 ? c / q : 0.0, t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tMin && t0 < tMax) return t0;
    if (t1 > tMin && t1 < tMax) return t1;
    return Infinity;
  }

  // The normal is normalised, not just divided by the radius: a hit point is on the sphere
  // only to round-off, and a frame built on a normal of length 1 + e reflects rays that are
  // 1 + e long, whose next hit is off by more again. A ray caught between near-critical
  // internal reflections in a glass sphere (dozens of bounces) would drift off the surface.
  SurfaceGeometry geometryAt(const Vec3d& point) const {
    const Vec3d n = glm::normalize(point - center);
    const Vec3d around = glm::cross(axis, n);  // d point / d phi
    const double length2 = glm::dot(around, around);
    return {n, length2 > 1e-24 ? around * (1.0 / std::sqrt(length2)) : Vec3d(0.0)};
  }

  // (phi / 2 pi, theta / pi) about the axis, in [0, 1]^2.
  Vec2d uvAt(const Vec3d& point) const {
    const Vec3d n = glm::normalize(point - center);
    const double cosTheta = std::clamp(glm::dot(n, axis), -1.0, 1.0);
    // phi measured from any fixed direction orthogonal to the axis: a frame around it.
    const Vec3d reference = std::abs(axis.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
    const Vec3d x = glm::normalize(reference - axis * glm::dot(axis, reference));
    const Vec3d y = glm::cross(axis, x);
    double phi = std::atan2(glm::dot(n, y), glm::dot(n, x));
    if (phi < 0) phi += 2.0 * Pi;
    return {phi * Inv2Pi, std::acos(cosTheta) * InvPi};
  }
};

// The infinite plane through `point` with unit `normal`; `tangent` (unit, orthogonal to the
// normal) orients anisotropic materials and the texture coordinates, which are distances
// along tangent and normal x tangent.
struct Plane {
  Vec3d point{0.0};
  Vec3d normal{0, 0, 1};
  Vec3d tangent{1, 0, 0};

  double intersect(const Ray& ray, double tMin, double tMax) const {
    const double denominator = glm::dot(ray.direction, normal);
    if (denominator == 0) return Infinity;
    const double t = glm::dot(point - ray.origin, normal) / denominator;
    return t > tMin && t < tMax ? t : Infinity;
  }

  SurfaceGeometry geometryAt(const Vec3d&) const { return {normal, tangent}; }

  Vec2d uvAt(const Vec3d& p) const {
    const Vec3d d = p - point;
    return {glm::dot(d, tangent), glm::dot(d, glm::cross(normal, tangent))};
  }
};

}  // namespace scatterlab
