#include "integrator/path_tracer.h"

#include <algorithm>

namespace scatterlab {

namespace {

// A shadow ray toward a light at finite distance stops this much short of it (relative), so
// that the light's own surface does not count as an occluder; far above double round-off.
constexpr double ShadowRayShortening = 1e-7;

constexpr LobeFlags NonDelta = LobeFlags::Diffuse | LobeFlags::Glossy;

}  // namespace

Rgb directLighting(const Scene& scene, const SurfaceInteraction& hit, const Bsdf& bsdf, const Vec3d& wi,
                   SampleStream& random, Estimator estimator, LightSet lightSet) {
  const double uSelect = random.next();
  const Vec2d u = random.next2D();
  const std::optional<LightSample> light = scene.sampleLight(hit.point, uSelect, u, lightSet);
  if (!light || !(light->pdf > 0)) return Rgb(0.0);
  const Vec3d& n = hit.geometry.normal;
  const double cosLight = glm::dot(n, light->direction);
  // A reflection-only model (two-sided) reflects nothing to the other side of the surface:
  // skip evaluating it there (half of a uniform light sample's directions).
  if (hit.twoSided() && cosLight * glm::dot(n, wi) <= 0) return Rgb(0.0);
  // Occlusion before the BSDF: for analytic shapes a shadow ray is cheaper than evaluating a
  // rough dielectric, and from inside a closed glass sphere every shadow ray is blocked.
  const double tMax = light->distance == Infinity ? Infinity : light->distance * (1.0 - ShadowRayShortening);
  if (scene.occluded(spawnRay(hit.point, n, light->direction), tMax)) return Rgb(0.0);
  const Rgb f = bsdf.eval(wi, light->direction);
  if (f == Rgb(0.0)) return Rgb(0.0);
  const double cosine = std::abs(cosLight);
  const double weight = light->isDelta || estimator != Estimator::Mis
                            ? 1.0
                            : powerHeuristic(light->pdf, bsdf.pdf(wi, light->direction));
  return f * light->radiance * (cosine * weight / light->pdf);
}

PathSample tracePath(const Scene& scene, const Ray& cameraRay, SampleStream& random,
                     const IntegratorSettings& settings) {
  PathSample out;
  Rgb throughput(1.0);
  double etaScale = 1.0;  // product of etaRel^2 over refractions (header comment)
  Ray ray = cameraRay;
  // How the current ray was chosen: by the camera or a delta lobe (no light sampling could
  // have found what it hits), or by a BSDF density `bsdfPdf` from `origin`.
  bool fromDelta = true;
  double bsdfPdf = 0.0;
  Vec3d origin = ray.origin;
  const Estimator estimator = settings.estimator;
  const LightSet lightSet = estimator == Estimator::Mis ? LightSet::MisSampled : LightSet::All;
  const bool nextEvent = estimator != Estimator::BsdfOnly && scene.lightCount(lightSet) > 0;
  // The weight of emission that the current ray finds, given the density with which NEE
  // would have sampled it.
  const auto emissionWeight = [&](double lightPdf) {
    if (fromDelta || estimator == Estimator::BsdfOnly) return 1.0;
    if (estimator == Estimator::LightOnly) return 0.0;
    return powerHeuristic(bsdfPdf, lightPdf);
  };
  // Scattering at a vertex reached from the side of wi: next-event estimation where the BSDF
  // has a lobe a light sample can meet, then one BSDF sample for the next direction.
  const auto scatter = [&](const SurfaceInteraction& vertex, const Bsdf& bsdf, const Vec3d& wi) {
    if (nextEvent && hasAny(bsdf.flags(), NonDelta))
      out.radiance += throughput * directLighting(scene, vertex, bsdf, wi, random, estimator, lightSet);
    const double uLobe = random.next();
    const Vec2d u = random.next2D();
    return bsdf.sample(wi, uLobe, u, TransportMode::Radiance);
  };
  // The path goes on from `point` (normal n) along a sampled direction.
  const auto continueAlong = [&](const Vec3d& point, const Vec3d& n, const BsdfSample& sample) {
    throughput *= sample.weight;
    if (hasAny(sample.lobe, LobeFlags::Transmission)) etaScale *= sample.eta * sample.eta;
    fromDelta = sample.isDelta();
    bsdfPdf = sample.pdf;
    origin = point;
    ray = spawnRay(point, n, sample.wo);
  };

  for (int bounce = 0;; ++bounce) {
    // ---- Find the next vertex; a ray that escapes receives the lights at infinity.
    const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (!hit) {
      out.radiance += throughput * scene.escapedRadiance(ray.direction, emissionWeight, lightSet);
      break;
    }
    ++out.vertices;
    const Vec3d wi = -ray.direction;
    if (bounce == 0) out.normal = hit->geometry.normal;

    // ---- Emission found by the ray, weighted against NEE's chance of sampling it.
    if (hit->light >= 0) {
      const Rgb emitted = scene.emitted(*hit, wi);
      if (emitted != Rgb(0.0))
        out.radiance += throughput * emitted * emissionWeight(scene.emittedPdf(*hit, origin, lightSet));
    }

    // ---- End the path after its last bounce.
    if (bounce >= settings.maxDepth) break;

    // ---- Scatter: next-event estimation, then a BSDF sample for the next direction.
    const std::optional<BsdfSample> sample = scatter(*hit, hit->bsdf(), wi);
    if (bounce == 0 && sample) out.albedo = sample->weight;
    if (!sample || sample->weight == Rgb(0.0)) break;

    if (entersMedium(*hit, wi, *sample)) {
      // ---- Subsurface material: the light leaves the medium elsewhere (subsurface.h).
      const std::optional<MediumExit> exit = leaveMedium(scene, *hit, *sample, random);
      if (!exit) break;
      throughput *= exit->weight;
      if (exit->vertex) {
        // Diffusion: the exit point scatters like any other vertex, with Sw as its BSDF.
        ++out.vertices;
        const Vec3d& n = exit->vertex->geometry.normal;
        const std::optional<BsdfSample> exitSample = scatter(*exit->vertex, exit->vertex->bsdf(), n);
        if (!exitSample) break;
        continueAlong(exit->vertex->point, n, *exitSample);
      } else {
        // The walk: no light was sampled where it left, so emission found next counts in full.
        fromDelta = true;
        origin = exit->ray.origin;
        ray = exit->ray;
      }
    } else {
      // ---- Continue along the sampled direction.
      continueAlong(hit->point, hit->geometry.normal, *sample);
    }

    // ---- Russian roulette (pbrt-v4 PathIntegrator::Li): survive with probability q = the
    // largest channel of throughput * etaScale, when below 1, and divide by it.
    if (bounce + 1 >= settings.rouletteDepth) {
      const Rgb scaled = throughput * etaScale;
      const double q = std::max({scaled.x, scaled.y, scaled.z});
      if (q < 1.0) {
        if (random.next() >= q) break;
        throughput /= q;
      }
    }
  }
  return out;
}

}  // namespace scatterlab
