// Light tracing: for camera sample s of pixel p, one light path (SampleStream part LightPath)
// carries importance from a light (emission.h, subpath.h: every BSDF sampled with
// TransportMode::Importance), and each of its surface vertices whose BSDF has a lobe that is
// not a delta is joined to the eye: beta f(wi, toward the eye) |cos| / d^2 times the pixel's
// importance, over N = width x height x spp light paths (splat_film.h). These are the
// strategies with t = 1 of BDPT (Veach 1997, ch. 10.2), each path made by exactly one of them,
// so no weights are needed.
//
// What no light path can reach: the pinhole (a point) is never hit, so light seen directly is
// found by the camera sample's own ray (the strategy s = 0, t = 2), as Mitsuba 3's particle
// tracer does; and a path whose first vertex from the eye scatters by a delta lobe (a mirror or
// smooth glass seen directly) cannot be joined to the eye at that vertex. Such pixels miss
// that light (a smooth mirror sphere shows only what it does not reflect specularly); the
// adjoint tests compare them only where the eye sees a surface without delta lobes.
#include "integrator/light_tracer.h"

#include <vector>

#include "integrator/emission.h"
#include "integrator/splat_film.h"
#include "integrator/subpath.h"

namespace scatterlab {

RenderResult renderLightTracing(const Scene& scene, const RenderSettings& settings,
                                const std::function<void(double)>& progress) {
  const LightEmission emission(scene);
  const SubpathSettings lightSubpath{settings.integrator.maxDepth, settings.integrator.rouletteDepth};
  const PinholeCamera& camera = scene.camera();
  const auto trace = [&](int x, int y, int sample, UnitRecorder& unit) {
    const uint64_t pixel = uint64_t(y) * uint64_t(camera.width()) + uint64_t(x);
    // ---- Light seen directly, by the camera sample's ray; and the first hit's layers.
    SampleStream cameraRandom(settings.seed, pixel, uint64_t(sample), StreamPart::Camera);
    const Vec2d film = Vec2d(x + 0.5, y + 0.5) + settings.filter.sampleOffset(cameraRandom);
    const Ray ray = camera.generateRay(film);
    const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (!hit) {
      unit.addCamera(scene.escapedRadiance(ray.direction, [](double) { return 1.0; }));
    } else {
      unit.addVertices(1);
      if (hit->light >= 0) unit.addCamera(scene.emitted(*hit, -ray.direction));
      Rgb albedo(0.0);
      if (settings.albedoLayer) {
        const double uLobe = cameraRandom.next();
        const Vec2d u = cameraRandom.next2D();
        if (const auto s = hit->bsdf().sample(-ray.direction, uLobe, u, TransportMode::Radiance))
          albedo = s->weight;
      }
      unit.setFirstHit(albedo, hit->geometry.normal);
    }

    // ---- One light path, every vertex seen by the eye.
    thread_local std::vector<PathVertex> path;
    SampleStream lightRandom(settings.seed, pixel, uint64_t(sample), StreamPart::LightPath);
    const SampleValue walk = traceLightSubpath(scene, emission, lightRandom, lightSubpath, path);
    if (path.empty()) return;
    unit.addVertices(path.size() - 1);
    if (walk != SampleValue::Valid) {
      unit.drop(walk);
      return;
    }
    for (size_t i = 1; i < path.size(); ++i) {
      if (!path[i].connectible()) continue;
      if (const std::optional<CameraConnection> c = connectToCamera(scene, path[i], settings.filter))
        unit.splat(c->film, c->value);
    }
  };
  return renderWithSplats(scene, settings, progress, trace);
}

}  // namespace scatterlab
