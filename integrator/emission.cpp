#include "integrator/emission.h"

#include <algorithm>
#include <cmath>

#include "materials/core/warp.h"

namespace scatterlab {

LightEmission::LightEmission(const Scene& scene) : scene_(&scene), bounds_(scene.finiteBounds()) {
  // Power sent into the scene, per light (luminance): a sphere light pi Le 4 pi r^2; light from
  // infinity what crosses the bounds' disk, pi R^2 times the integral of Le over directions
  // (a sun: its irradiance).
  const double disk = Pi * bounds_.radius * bounds_.radius;
  for (const LightRef& light : scene.lights()) {
    double power = 0.0;
    switch (light.kind) {
      case LightKind::Environment: power = scene.environment()->luminanceIntegral() * disk; break;
      case LightKind::Sphere: {
        const SphereLight& s = scene.sphereLights()[size_t(light.index)];
        power = Pi * 4.0 * Pi * s.sphere.radius * s.sphere.radius * luminance(s.radiance);
        break;
      }
      case LightKind::Sun: power = luminance(scene.suns()[size_t(light.index)].irradiance()) * disk; break;
    }
    probability_.push_back(std::max(power, 0.0));
    total_ += probability_.back();
  }
  double sum = 0.0;
  for (double& p : probability_) {
    p = total_ > 0 ? p / total_ : 0.0;
    sum += p;
    cumulative_.push_back(sum);
  }
}

double LightEmission::spherePositionPdf(int light) const {
  const double r = scene_->sphereLights()[size_t(scene_->lights()[size_t(light)].index)].sphere.radius;
  return selectionProbability(light) / (4.0 * Pi * r * r);
}

double LightEmission::infiniteDirectionPdf(int light, const Vec3d& travel) const {
  const LightRef& ref = scene_->lights()[size_t(light)];
  if (ref.kind == LightKind::Environment)
    return selectionProbability(light) * scene_->environment()->pdf(-travel);
  const SunLight& sun = scene_->suns()[size_t(ref.index)];
  return selectionProbability(light) * (sun.isDelta() ? 1.0 : sun.pdf(-travel));
}

double LightEmission::perpendicularPdf(const Vec3d& point, const Vec3d& travel) const {
  const Vec3d offset = point - bounds_.center;
  const double rho2 = std::max(glm::dot(offset, offset) - sqr(glm::dot(offset, travel)), 0.0);
  const double r = bounds_.radius;
  return r / (2.0 * Pi * std::pow(r * r + rho2, 1.5));
}

std::optional<EmittedRay> LightEmission::sample(SampleStream& random) const {
  if (!(total_ > 0)) return std::nullopt;
  const double uSelect = random.next();
  const Vec2d uPosition = random.next2D();
  const Vec2d uDirection = random.next2D();
  const int light = int(std::min<size_t>(
      size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), uSelect) - cumulative_.begin()),
      cumulative_.size() - 1));
  const double select = probability_[size_t(light)];
  if (!(select > 0)) return std::nullopt;
  const LightRef& ref = scene_->lights()[size_t(light)];
  EmittedRay out;
  out.light = light;

  if (ref.kind == LightKind::Sphere) {
    const SphereLight& s = scene_->sphereLights()[size_t(ref.index)];
    const Vec3d n = sampleUniformSphere(uPosition);
    const Vec3d local = sampleCosineHemisphere(uDirection);
    if (!(local.z > 0)) return std::nullopt;
    const Vec3d w = Framed::fromNormal(n).toWorld(local);
    const Vec3d origin = s.sphere.center + s.sphere.radius * n;
    out.ray = spawnRay(origin, n, w);
    out.normal = n;
    out.pdfLight = select / (4.0 * Pi * s.sphere.radius * s.sphere.radius);
    out.pdfNext = local.z * InvPi;
    out.weight = s.radiance * (local.z / (out.pdfLight * out.pdfNext));
    return out;
  }

  // Light from infinity: a direction, then the line's point on the perpendicular plane.
  Vec3d toward;
  Rgb radiance;
  double directionPdf;
  if (ref.kind == LightKind::Environment) {
    const std::optional<EnvironmentSample> e = scene_->environment()->sample(uDirection);
    if (!e || !(e->pdf > 0)) return std::nullopt;
    toward = e->direction;
    radiance = e->radiance;
    directionPdf = e->pdf;
  } else {
    const std::optional<LightSample> l = scene_->suns()[size_t(ref.index)].sample(uDirection);
    if (!l) return std::nullopt;
    toward = l->direction;
    radiance = l->radiance;  // a delta sun: its irradiance
    directionPdf = l->isDelta ? 1.0 : l->pdf;
    out.deltaDirection = l->isDelta;
  }
  const Vec3d travel = -toward;
  const double r = bounds_.radius;
  const double rho = r * std::sqrt(std::max(1.0 / sqr(1.0 - uPosition.x) - 1.0, 0.0));
  const double phi = 2.0 * Pi * uPosition.y;
  const Framed frame = Framed::fromNormal(travel);
  const Vec3d through = bounds_.center + rho * (std::cos(phi) * frame.s + std::sin(phi) * frame.t);
  out.ray = scene_->rayFromInfinity(through, travel);
  out.atInfinity = true;
  out.pdfLight = select * directionPdf;
  out.pdfNext = r / (2.0 * Pi * std::pow(r * r + rho * rho, 1.5));
  out.weight = radiance / (out.pdfLight * out.pdfNext);
  if (!isFinite(out.weight)) return std::nullopt;
  return out;
}

}  // namespace scatterlab
