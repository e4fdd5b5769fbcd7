#include "integrator/lights.h"

#include <cmath>
#include <stdexcept>

#include "materials/core/warp.h"

namespace scatterlab {

namespace {

// Below this, 1 - cos theta_max = sin^2 / 2 to first order; 1 - sqrt(1 - s) would lose the
// digits that matter (pbrt-v4 uses the same threshold, sin^2 of 1.5 degrees).
constexpr double SmallConeSin2 = 0.00068523;

struct Cone {
  double sin2Max, cosMax, oneMinusCosMax;
};

Cone coneOf(double sin2Max) {
  const double cosMax = safeSqrt(1.0 - sin2Max);
  return {sin2Max, cosMax, sin2Max < SmallConeSin2 ? sin2Max / 2.0 : 1.0 - cosMax};
}

}  // namespace

std::optional<LightSample> SphereLight::sample(const Vec3d& p, const Vec2d& u) const {
  const Vec3d toCenter = sphere.center - p;
  const double distance2 = glm::dot(toCenter, toCenter);
  const double r2 = sphere.radius * sphere.radius;
  if (!(distance2 > r2)) return std::nullopt;  // inside: a one-sided emitter is invisible
  const Cone cone = coneOf(r2 / distance2);
  // cos theta uniform in [cos theta_max, 1] (in sin^2 for a small cone).
  double cosTheta, sin2Theta;
  if (cone.sin2Max < SmallConeSin2) {
    sin2Theta = cone.sin2Max * u.x;
    cosTheta = std::sqrt(1.0 - sin2Theta);
  } else {
    cosTheta = (cone.cosMax - 1.0) * u.x + 1.0;
    sin2Theta = 1.0 - cosTheta * cosTheta;
  }
  // The angle alpha at the centre between -toCenter and the point seen at theta.
  const double sinThetaMax = std::sqrt(cone.sin2Max);
  const double cosAlpha = sin2Theta / sinThetaMax + cosTheta * safeSqrt(1.0 - sin2Theta / cone.sin2Max);
  const double sinAlpha = safeSqrt(1.0 - cosAlpha * cosAlpha);
  const double phi = 2.0 * Pi * u.y;
  const Framed frame = Framed::fromNormal(glm::normalize(toCenter));
  const Vec3d normal = frame.toWorld(Vec3d(-sinAlpha * std::cos(phi), -sinAlpha * std::sin(phi), -cosAlpha));
  const Vec3d point = sphere.center + sphere.radius * normal;
  const Vec3d toPoint = point - p;
  const double distance = glm::length(toPoint);
  if (!(distance > 0)) return std::nullopt;
  return LightSample{toPoint / distance, distance, radiance, 1.0 / (2.0 * Pi * cone.oneMinusCosMax), false};
}

double SphereLight::pdf(const Vec3d& p) const {
  const Vec3d toCenter = sphere.center - p;
  const double distance2 = glm::dot(toCenter, toCenter);
  const double r2 = sphere.radius * sphere.radius;
  if (!(distance2 > r2)) return 0.0;
  return 1.0 / (2.0 * Pi * coneOf(r2 / distance2).oneMinusCosMax);
}

SunLight::SunLight(const Vec3d& direction, const Rgb& irradiance, double angularRadiusDegrees)
    : irradiance_(irradiance) {
  if (!(glm::length(direction) > 0) || !isFinite(direction))
    throw std::invalid_argument("SunLight: direction must be a finite non-zero vector");
  if (!isFinite(irradiance) || irradiance.x < 0 || irradiance.y < 0 || irradiance.z < 0)
    throw std::invalid_argument("SunLight: irradiance must be finite and >= 0");
  if (!(angularRadiusDegrees >= 0 && angularRadiusDegrees < 90))
    throw std::invalid_argument("SunLight: angular radius must be in [0, 90) degrees");
  frame_ = Framed::fromNormal(glm::normalize(direction));
  const double delta = radians(angularRadiusDegrees);
  cosRadius_ = std::cos(delta);
  if (angularRadiusDegrees == 0) {
    cosRadius_ = 1.0;
    radiance_ = Rgb(0.0);
    conePdf_ = 0.0;
  } else {
    const double sinDelta = std::sin(delta);
    radiance_ = irradiance / (Pi * sinDelta * sinDelta);
    // 1 - cos delta = 2 sin^2(delta / 2), without cancellation for a small sun.
    conePdf_ = 1.0 / (2.0 * Pi * 2.0 * sqr(std::sin(delta / 2.0)));
  }
}

std::optional<LightSample> SunLight::sample(const Vec2d& u) const {
  if (isDelta()) return LightSample{frame_.n, Infinity, irradiance_, 1.0, true};
  const Vec3d local = sampleUniformCone(u, cosRadius_);
  return LightSample{glm::normalize(frame_.toWorld(local)), Infinity, radiance_, conePdf_, false};
}

Rgb SunLight::eval(const Vec3d& direction) const {
  if (isDelta() || glm::dot(direction, frame_.n) < cosRadius_) return Rgb(0.0);
  return radiance_;
}

double SunLight::pdf(const Vec3d& direction) const {
  if (isDelta() || glm::dot(direction, frame_.n) < cosRadius_) return 0.0;
  return conePdf_;
}

}  // namespace scatterlab
