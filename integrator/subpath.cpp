#include "integrator/subpath.h"

#include <algorithm>
#include <cmath>

namespace scatterlab {

namespace {

// How the ray that a walk follows was drawn: with `pdf` per unit solid angle from the last
// vertex, per unit area of the plane perpendicular to it (light from infinity), or by a delta.
struct RayDensity {
  double pdf;
  bool perpendicular = false;
  bool delta = false;
};

// The density of reaching `to` by a ray drawn from `from` with `density`.
double arrivalDensity(const RayDensity& density, const PathVertex& from, const SurfaceInteraction& to,
                      const Vec3d& direction) {
  if (density.delta) return 1.0;
  if (density.perpendicular) return density.pdf * std::abs(glm::dot(to.geometry.normal, direction));
  return toAreaDensity(density.pdf, from.point(), to.point, to.geometry.normal);
}

// The density, in the measure of vertex `before`, of reaching it from `vertex` by a direction
// drawn there with `pdf` per unit solid angle (1 after a delta).
double reverseDensity(double pdf, bool delta, const PathVertex& vertex, const PathVertex& before) {
  if (delta) return 1.0;
  switch (before.kind) {
    case PathVertex::Kind::Eye: return 0.0;  // a pinhole is never hit
    case PathVertex::Kind::Light:
      return before.atInfinity ? pdf : toAreaDensity(pdf, vertex.point(), before.point(), before.normal());
    case PathVertex::Kind::Surface: break;
  }
  return toAreaDensity(pdf, vertex.point(), before.point(), before.normal());
}

// Continues the subpath in `path` (its start already in it) along `ray`, appending surface
// vertices: the random walk both ends share, in their transport mode. Returns Valid, or the
// kind of the invalid throughput it ended on (subpath.h).
SampleValue walk(const Scene& scene, Ray ray, Rgb beta, RayDensity density, TransportMode mode,
                 SampleStream& random, const SubpathSettings& settings, std::vector<PathVertex>& path) {
  const int start = int(path.size());  // vertices before the walk's first
  const TransportMode reverseMode =
      mode == TransportMode::Radiance ? TransportMode::Importance : TransportMode::Radiance;
  const double startScale = std::max({beta.x, beta.y, beta.z});
  double etaScale = 1.0;
  for (int bounces = 0;; ++bounces) {
    if (int(path.size()) - start >= settings.maxVertices) return SampleValue::Valid;
    const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (!hit) {
      if (mode == TransportMode::Radiance) {  // the camera ray escapes: the lights at infinity
        PathVertex escaped;
        escaped.atInfinity = true;
        escaped.direction = ray.direction;
        escaped.wi = -ray.direction;
        escaped.beta = beta;
        escaped.pdfForward = density.delta ? 1.0 : density.pdf;
        path.push_back(escaped);
      }
      return SampleValue::Valid;
    }
    PathVertex vertex;
    vertex.hit = *hit;
    vertex.wi = -ray.direction;
    vertex.beta = beta;
    vertex.pdfForward = arrivalDensity(density, path.back(), *hit, ray.direction);
    path.push_back(vertex);
    if (hit->light >= 0) return SampleValue::Valid;  // emitters reflect nothing
    if (int(path.size()) - start >= settings.maxVertices) return SampleValue::Valid;

    const Bsdf bsdf = hit->bsdf();
    const double uLobe = random.next();
    const Vec2d u = random.next2D();
    const std::optional<BsdfSample> sample = bsdf.sample(vertex.wi, uLobe, u, mode);
    if (!sample || sample->weight == Rgb(0.0)) return SampleValue::Valid;
    PathVertex& here = path.back();
    here.delta = sample->isDelta();
    const double reversePdf = here.delta ? 1.0 : bsdf.pdf(sample->wo, here.wi, reverseMode);
    path[path.size() - 2].pdfReverse = reverseDensity(reversePdf, here.delta, here, path[path.size() - 2]);

    beta *= sample->weight;
    // As in the path tracer: a throughput that is not finite or negative ends the walk, which
    // says so, where a silent end would look like absorbed light (sample_value.h).
    if (const SampleValue value = classifyValue(beta); value != SampleValue::Valid) return value;
    if (hasAny(sample->lobe, LobeFlags::Transmission)) etaScale *= sample->eta * sample->eta;
    density = RayDensity{sample->pdf, false, here.delta};
    ray = spawnRay(here.point(), here.normal(), sample->wo);
    if (bounces + 1 >= settings.rouletteDepth) {
      // The camera's throughput is measured without the radiance scaling of refractions, the
      // light's relative to its start (header comment).
      const Rgb scaled = mode == TransportMode::Radiance ? beta * etaScale : beta / startScale;
      const double q = std::max({scaled.x, scaled.y, scaled.z});
      if (q < 1.0) {
        if (random.next() >= q) return SampleValue::Valid;
        beta /= q;
      }
    }
  }
}

}  // namespace

double toAreaDensity(double pdfSolidAngle, const Vec3d& from, const Vec3d& to, const Vec3d& toNormal) {
  const Vec3d d = to - from;
  const double distance2 = glm::dot(d, d);
  if (!(distance2 > 0)) return 0.0;
  return pdfSolidAngle * std::abs(glm::dot(toNormal, d)) / (distance2 * std::sqrt(distance2));
}

SampleValue traceCameraSubpath(const Scene& scene, const Vec2d& film, SampleStream& random,
                               const SubpathSettings& settings, std::vector<PathVertex>& out) {
  out.clear();
  const PinholeCamera& camera = scene.camera();
  PathVertex eye;
  eye.kind = PathVertex::Kind::Eye;
  eye.hit.point = camera.eye();
  eye.pdfForward = 1.0;
  out.push_back(eye);
  const Ray ray = camera.generateRay(film);
  const double pdf = camera.directionPdf(glm::dot(ray.direction, camera.forward()));
  return walk(scene, ray, Rgb(1.0), RayDensity{pdf}, TransportMode::Radiance, random, settings, out);
}

SampleValue traceLightSubpath(const Scene& scene, const LightEmission& emission, SampleStream& random,
                              const SubpathSettings& settings, std::vector<PathVertex>& out) {
  out.clear();
  const std::optional<EmittedRay> emitted = emission.sample(random);
  if (!emitted) return SampleValue::Valid;
  PathVertex light;
  light.kind = PathVertex::Kind::Light;
  light.light = emitted->light;
  light.hit.point = emitted->ray.origin;
  light.hit.geometry.normal = emitted->normal;
  light.direction = emitted->ray.direction;
  light.atInfinity = emitted->atInfinity;
  light.deltaLight = emitted->deltaDirection;
  light.pdfForward = emitted->pdfLight;
  out.push_back(light);
  return walk(scene, emitted->ray, emitted->weight, RayDensity{emitted->pdfNext, emitted->atInfinity},
              TransportMode::Importance, random, settings, out);
}

std::optional<CameraConnection> connectToCamera(const Scene& scene, const PathVertex& vertex,
                                                const PixelFilter& filter) {
  const PinholeCamera& camera = scene.camera();
  const Vec3d toEye = camera.eye() - vertex.point();
  const double distance = glm::length(toEye);
  if (!(distance > 0)) return std::nullopt;
  const Vec3d w = toEye / distance;
  const std::optional<FilmPoint> film = camera.filmPoint(-w, std::max(filter.radius() - 0.5, 0.0));
  if (!film) return std::nullopt;
  const Rgb f = vertex.hit.bsdf().eval(vertex.wi, w, TransportMode::Importance);
  if (f == Rgb(0.0)) return std::nullopt;
  if (scene.occluded(spawnRay(vertex.point(), vertex.normal(), w), distance)) return std::nullopt;
  const double cosine = std::abs(glm::dot(vertex.normal(), w));
  const Rgb value =
      vertex.beta * f * (cosine / (distance * distance) * camera.pixelImportance(film->cosTheta));
  return CameraConnection{film->position, value, w, distance, film->cosTheta};
}

}  // namespace scatterlab
