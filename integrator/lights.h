// Lights other than the environment: spheres that emit (area lights) and a distant sun.
//
// Every light is sampled by direction from the shading point, with a density per unit solid
// angle, so that next-event estimation and BSDF sampling can be combined by multiple
// importance sampling in one measure.
#pragma once

#include <optional>

#include "integrator/ray.h"
#include "integrator/shapes.h"
#include "materials/core/frame.h"

namespace scatterlab {

struct LightSample {
  Vec3d direction;  // unit, from the shading point toward the light
  double distance;  // to the light's surface; Infinity for lights at infinity
  Rgb radiance;     // arriving along -direction; for a delta light, the irradiance it gives
  double pdf;       // per unit solid angle; for a delta light, 1
  bool isDelta = false;
  int light = -1;  // which light of the set Scene::sampleLight chose from (Scene::lights)
};

// A sphere emitting `radiance` uniformly from its outside (one-sided: nothing toward its
// inside). Sampled within the cone it subtends from the shading point, uniformly, with the
// point on the sphere computed geometrically rather than by intersecting a ray with it, so a
// direction at the cone's rim never misses (pbrt-v4 Sphere::Sample; Pharr, Jakob & Humphreys,
// 4th ed., sec. 6.2.4). Seen from inside it gives nothing.
struct SphereLight {
  Sphere sphere;
  Rgb radiance{1.0};

  std::optional<LightSample> sample(const Vec3d& p, const Vec2d& u) const;
  // Density of sample() for a direction from p that hits the sphere's outside.
  double pdf(const Vec3d& p) const;
};

// The sun: irradiance E (at normal incidence, per channel) from a disk of angular radius
// delta around `direction`, radiance L = E / (pi sin^2 delta) inside the disk (the integral
// of L cos over the disk is L pi sin^2 delta). delta = 0 makes it a delta light, which only
// next-event estimation can find.
class SunLight {
 public:
  // direction: toward the sun (normalised here); irradiance finite and >= 0; angular radius
  // in [0, 90) degrees. std::invalid_argument otherwise.
  SunLight(const Vec3d& direction, const Rgb& irradiance, double angularRadiusDegrees = 0.0);

  bool isDelta() const { return cosRadius_ == 1.0; }
  std::optional<LightSample> sample(const Vec2d& u) const;
  // Radiance seen along `direction` (0 for a delta sun: it occupies no solid angle).
  Rgb eval(const Vec3d& direction) const;
  double pdf(const Vec3d& direction) const;

  const Vec3d& direction() const { return frame_.n; }
  const Rgb& irradiance() const { return irradiance_; }

 private:
  Framed frame_;
  Rgb irradiance_, radiance_;
  double cosRadius_;
  double conePdf_;  // 1 / (2 pi (1 - cos delta))
};

}  // namespace scatterlab
