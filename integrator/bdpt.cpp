// Bidirectional path tracing (Veach 1997, ch. 10; Veach & Guibas 1995; Lafortune & Willems
// 1993). Every camera sample traces a camera subpath z_0 (the eye), z_1, ... and a light subpath
// y_0 (on a light), y_1, ... (subpath.h), and every pair of prefixes (s light vertices, t camera
// vertices) makes a path of s + t vertices, s + t - 2 bounces, up to maxDepth:
//   s = 0:      the camera subpath found a light (an emitter, or the lights at infinity);
//   s = 1:      next-event estimation: a light point sampled from z_{t-1} (Scene::sampleLight);
//   s, t >= 2:  y_{s-1} and z_{t-1} joined by a shadow ray;
//   t = 1:      y_{s-1} seen by the eye, added where it lands on the film (splat_film.h).
// (s = 1, t = 1), a light seen directly, is left to (s = 0, t = 2).
//
// Each strategy's contribution is weighted by the power heuristic over every strategy that
// could have made the same path (Veach 1997, eq. 10.9 with beta = 2):
//   w_s = p_s^2 / sum_j p_j^2,   p_j = prod_{i<j} pL(x_i) prod_{i>=j} pC(x_i),
// with x_0 ... x_n the path from the light to the eye, pL and pC the densities of a vertex as the
// light and the camera end would make it. p_j / p_s is a product of ratios pL(x_i) / pC(x_i),
// computed in one pass. One refinement over the textbook recurrence: the light's vertex x_0 has
// three densities, one per kind of strategy, each the density that strategy really draws it
// with: pC(x_0) (the camera's BSDF sample) for s = 0, next-event estimation's for s = 1, and
// emission's (emission.h) for s >= 2. A strategy that cannot make the path (a connection at a
// delta vertex, a delta sun found by BSDF sampling, the eye found by a light path) has p_j = 0.
#include "integrator/bdpt.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "integrator/emission.h"
#include "integrator/splat_film.h"
#include "integrator/subpath.h"

namespace scatterlab {

namespace {

// The densities of the path x_0 ... x_n made by one strategy, as the MIS weight needs them.
struct PathDensities {
  int n = 0;                          // the eye's index
  std::vector<double> light, camera;  // pL(x_i), pC(x_i); light[0] unused (x_0's are below)
  std::vector<bool> delta;
  double x0Camera = 0.0, x0NextEvent = 0.0, x0Emission = 0.0;

  void reset(int eye) {
    n = eye;
    light.assign(size_t(eye) + 1, 0.0);
    camera.assign(size_t(eye) + 1, 0.0);
    delta.assign(size_t(eye) + 1, false);
    camera[size_t(eye)] = 1.0;  // every strategy with t >= 1 has the one eye
    x0Camera = x0NextEvent = x0Emission = 0.0;
  }

  // Can strategy j (j light vertices) make this path? (header comment)
  bool possible(int j) const {
    if (j == 0) return x0Camera > 0;
    if (j == 1) return n >= 2 && x0NextEvent > 0 && !delta[1];
    if (j > n) return false;
    return n >= 2 && !delta[size_t(j - 1)] && (j == n || !delta[size_t(j)]);
  }
  double x0Density(int j) const { return j == 0 ? x0Camera : j == 1 ? x0NextEvent : x0Emission; }

  // The power-heuristic weight of strategy s.
  double weight(int s) const {
    // R_j = P_j / P_{s'} over j >= 1, P_j the product without x_0's density, s' = max(s, 1);
    // strategy 0 shares P_1.
    const int base = std::max(s, 1);
    const double own = x0Density(s);
    if (!(own > 0)) return 0.0;
    double sum = 0.0;
    const auto add = [&](int j, double ratio) {
      if (possible(j)) sum += sqr(x0Density(j) * ratio / own);
    };
    double ratio = 1.0;
    add(base, 1.0);
    if (base == 1) add(0, 1.0);
    for (int j = base + 1; j <= n; ++j) {
      if (!(camera[size_t(j - 1)] > 0)) return 0.0;  // a zero-density vertex the camera made: measure zero
      ratio *= light[size_t(j - 1)] / camera[size_t(j - 1)];
      add(j, ratio);
    }
    ratio = 1.0;
    for (int j = base - 1; j >= 1; --j) {
      if (!(light[size_t(j)] > 0)) return 0.0;
      ratio *= camera[size_t(j)] / light[size_t(j)];
      add(j, ratio);
      if (j == 1) add(0, ratio);
    }
    return sum > 0 ? 1.0 / sum : 0.0;
  }
};

class Bdpt {
 public:
  Bdpt(const Scene& scene, const RenderSettings& settings)
      : scene_(scene),
        settings_(settings),
        emission_(scene),
        camera_{settings.integrator.maxDepth + 1, settings.integrator.rouletteDepth},
        light_{settings.integrator.maxDepth, settings.integrator.rouletteDepth},
        eyeOnly_(1) {
    eyeOnly_[0].kind = PathVertex::Kind::Eye;
  }

  void trace(int x, int y, int sample, UnitRecorder& unit) const {
    thread_local std::vector<PathVertex> cameraPath, lightPath;
    thread_local PathDensities densities;
    const uint64_t pixel = uint64_t(y) * uint64_t(scene_.camera().width()) + uint64_t(x);
    SampleStream cameraRandom(settings_.seed, pixel, uint64_t(sample), StreamPart::Camera);
    const Vec2d film = Vec2d(x + 0.5, y + 0.5) + settings_.filter.sampleOffset(cameraRandom);
    const SampleValue cameraWalk = traceCameraSubpath(scene_, film, cameraRandom, camera_, cameraPath);
    SampleStream lightRandom(settings_.seed, pixel, uint64_t(sample), StreamPart::LightPath);
    const SampleValue lightWalk = traceLightSubpath(scene_, emission_, lightRandom, light_, lightPath);
    unit.addVertices(cameraPath.size() - 1 + (lightPath.empty() ? 0 : lightPath.size() - 1));
    // A subpath that ended on an invalid weight drops the whole unit (splat_film.h): every
    // strategy's path is made of both.
    if (cameraWalk != SampleValue::Valid) {
      unit.drop(cameraWalk);
      return;
    }
    if (lightWalk != SampleValue::Valid) {
      unit.drop(lightWalk);
      return;
    }
    if (cameraPath.size() > 1 && !cameraPath[1].atInfinity)
      unit.setFirstHit(firstAlbedo(cameraPath), cameraPath[1].normal());

    const int maxDepth = settings_.integrator.maxDepth;
    Rgb radiance(0.0);
    for (int t = 1; t <= int(cameraPath.size()); ++t)
      for (int s = 0; s <= int(lightPath.size()); ++s) {
        const int depth = s + t - 2;
        if (depth < 0 || depth > maxDepth || (s == 1 && t == 1) || (s == 0 && t == 1)) continue;
        if (t == 1) {
          connectToEye(lightPath, s, densities, unit);
        } else if (s == 0) {
          radiance += foundLight(cameraPath, t, densities);
        } else if (s == 1) {
          radiance += nextEvent(cameraPath, t, cameraRandom, densities);
        } else {
          radiance += connect(lightPath, s, cameraPath, t, densities);
        }
      }
    unit.addCamera(radiance);
  }

 private:
  // The path tracer's albedo layer, the first vertex's BSDF sample weight, is the throughput
  // with which the camera subpath reached z_2 (Russian roulette starts later).
  static Rgb firstAlbedo(const std::vector<PathVertex>& path) {
    return path.size() > 2 ? path[2].beta : Rgb(0.0);
  }

  // Fills the densities of the path made of light vertices 0 .. s-1 and camera vertices
  // t-1 .. 0, from what the subpaths stored.
  static void gather(const std::vector<PathVertex>& lightPath, int s,
                     const std::vector<PathVertex>& cameraPath, int t, PathDensities& d) {
    d.reset(s + t - 1);
    for (int i = 0; i < s; ++i) {
      const PathVertex& v = lightPath[size_t(i)];
      d.light[size_t(i)] = v.pdfForward;
      d.camera[size_t(i)] = v.pdfReverse;
      d.delta[size_t(i)] = v.delta;
    }
    for (int j = 0; j < t; ++j) {
      const PathVertex& v = cameraPath[size_t(t - 1 - j)];
      const size_t i = size_t(s + j);
      d.camera[i] = v.pdfForward;
      d.light[i] = v.pdfReverse;
      d.delta[i] = v.delta;
    }
    d.camera[size_t(d.n)] = 1.0;
    d.light[size_t(d.n)] = 0.0;
  }

  // The density, at vertex `to`, of a direction drawn at `at` with `pdf` per unit solid angle.
  static double densityAt(double pdf, const Vec3d& at, const PathVertex& to) {
    if (to.kind == PathVertex::Kind::Eye) return 0.0;
    if (to.kind == PathVertex::Kind::Light && to.atInfinity) return pdf;
    return toAreaDensity(pdf, at, to.point(), to.normal());
  }

  // The light's three densities of x_0 and the emission density of x_1 when x_0 lies on sphere
  // light `light` (index into Scene::lights()) at `point`, normal n0, and x_1 at `next`.
  void sphereLightDensities(int light, const Vec3d& point, const Vec3d& n0, const PathVertex& next,
                            PathDensities& d) const {
    const SphereLight& sphere = scene_.sphereLights()[size_t(scene_.lights()[size_t(light)].index)];
    d.x0NextEvent = next.kind == PathVertex::Kind::Eye
                        ? 0.0
                        : toAreaDensity(scene_.lightSelectionProbability() * sphere.pdf(next.point()),
                                        next.point(), point, n0);
    d.x0Emission = emission_.spherePositionPdf(light);
    const Vec3d toNext = glm::normalize(next.point() - point);
    d.light[1] = next.kind == PathVertex::Kind::Eye
                     ? 0.0
                     : toAreaDensity(LightEmission::sphereDirectionPdf(n0, toNext), point, next.point(),
                                     next.normal());
  }

  // The same for light at infinity `light` arriving along -travel at x_1.
  void infiniteLightDensities(int light, const Vec3d& travel, const PathVertex& next,
                              PathDensities& d) const {
    const LightRef& ref = scene_.lights()[size_t(light)];
    const double select = scene_.lightSelectionProbability();
    if (ref.kind == LightKind::Environment) {
      d.x0NextEvent = select * scene_.environment()->pdf(-travel);
    } else {
      const SunLight& sun = scene_.suns()[size_t(ref.index)];
      d.x0NextEvent = sun.isDelta() ? select : select * sun.pdf(-travel);
      if (sun.isDelta()) d.x0Camera = 0.0;  // no BSDF sample finds a single direction
    }
    d.x0Emission = emission_.infiniteDirectionPdf(light, travel);
    d.light[1] = next.kind == PathVertex::Kind::Eye ? 0.0
                                                    : emission_.perpendicularPdf(next.point(), travel) *
                                                          std::abs(glm::dot(next.normal(), travel));
  }

  // s = 0: z_{t-1} is on a sphere light, or the camera ray escaped to the lights at infinity.
  Rgb foundLight(const std::vector<PathVertex>& cameraPath, int t, PathDensities& d) const {
    const PathVertex& z = cameraPath[size_t(t - 1)];
    const PathVertex& previous = cameraPath[size_t(t - 2)];
    if (z.atInfinity) {
      Rgb sum(0.0);
      const std::vector<LightRef>& lights = scene_.lights();
      for (int light = 0; light < int(lights.size()); ++light) {
        Rgb le(0.0);
        if (lights[size_t(light)].kind == LightKind::Environment)
          le = scene_.environment()->eval(z.direction);
        else if (lights[size_t(light)].kind == LightKind::Sun)
          le = scene_.suns()[size_t(lights[size_t(light)].index)].eval(z.direction);
        if (le == Rgb(0.0)) continue;
        gather({}, 0, cameraPath, t, d);
        d.x0Camera = z.pdfForward;
        infiniteLightDensities(light, -z.direction, previous, d);
        sum += z.beta * le * d.weight(0);
      }
      return sum;
    }
    if (z.hit.light < 0) return Rgb(0.0);
    const Rgb le = scene_.emitted(z.hit, z.wi);
    if (le == Rgb(0.0)) return Rgb(0.0);
    gather({}, 0, cameraPath, t, d);
    d.x0Camera = z.pdfForward;
    sphereLightDensities(scene_.lightIndex(LightKind::Sphere, z.hit.light), z.point(), z.normal(), previous,
                         d);
    return z.beta * le * d.weight(0);
  }

  // s = 1: a light sampled from z_{t-1}.
  Rgb nextEvent(const std::vector<PathVertex>& cameraPath, int t, SampleStream& random,
                PathDensities& d) const {
    const PathVertex& z = cameraPath[size_t(t - 1)];
    if (!z.connectible()) return Rgb(0.0);
    const double uSelect = random.next();
    const Vec2d u = random.next2D();
    const std::optional<LightSample> light = scene_.sampleLight(z.point(), uSelect, u);
    if (!light || !(light->pdf > 0)) return Rgb(0.0);
    const Bsdf bsdf = z.hit.bsdf();
    const Rgb f = bsdf.eval(z.wi, light->direction, TransportMode::Radiance);
    if (f == Rgb(0.0)) return Rgb(0.0);
    const double tMax = light->distance == Infinity ? Infinity : light->distance * (1.0 - 1e-7);
    if (scene_.occluded(spawnRay(z.point(), z.normal(), light->direction), tMax)) return Rgb(0.0);
    const Rgb contribution =
        z.beta * f * light->radiance * (std::abs(glm::dot(z.normal(), light->direction)) / light->pdf);

    d.reset(t);  // x_0 the light, x_1 .. x_t the camera vertices t-1 .. 0
    for (int j = 0; j < t; ++j) {
      const PathVertex& v = cameraPath[size_t(t - 1 - j)];
      d.camera[size_t(1 + j)] = v.pdfForward;
      d.light[size_t(1 + j)] = v.pdfReverse;
      d.delta[size_t(1 + j)] = v.delta;
    }
    d.delta[1] = false;
    d.camera[size_t(d.n)] = 1.0;
    d.light[size_t(d.n)] = 0.0;
    // x_2 as the light would make it: z's BSDF sampled from the light's side.
    if (t >= 2) {
      const PathVertex& before = cameraPath[size_t(t - 2)];
      d.light[2] = densityAt(bsdf.pdf(light->direction, z.wi, TransportMode::Importance), z.point(), before);
    }
    const LightRef& ref = scene_.lights()[size_t(light->light)];
    if (ref.kind == LightKind::Sphere) {
      const SphereLight& sphere = scene_.sphereLights()[size_t(ref.index)];
      const Vec3d point = z.point() + light->distance * light->direction;
      const Vec3d n0 = glm::normalize(point - sphere.sphere.center);
      d.x0Camera =
          toAreaDensity(bsdf.pdf(z.wi, light->direction, TransportMode::Radiance), z.point(), point, n0);
      sphereLightDensities(light->light, point, n0, z, d);
    } else {
      d.x0Camera = bsdf.pdf(z.wi, light->direction, TransportMode::Radiance);
      infiniteLightDensities(light->light, -light->direction, z, d);
    }
    return contribution * d.weight(1);
  }

  // s, t >= 2: y_{s-1} joined to z_{t-1}.
  Rgb connect(const std::vector<PathVertex>& lightPath, int s, const std::vector<PathVertex>& cameraPath,
              int t, PathDensities& d) const {
    const PathVertex& y = lightPath[size_t(s - 1)];
    const PathVertex& z = cameraPath[size_t(t - 1)];
    if (!y.connectible() || !z.connectible()) return Rgb(0.0);
    const Vec3d edge = y.point() - z.point();
    const double distance2 = glm::dot(edge, edge);
    if (!(distance2 > 0)) return Rgb(0.0);
    const double distance = std::sqrt(distance2);
    const Vec3d toY = edge / distance;
    const Bsdf bsdfY = y.hit.bsdf(), bsdfZ = z.hit.bsdf();
    const Rgb fY = bsdfY.eval(y.wi, -toY, TransportMode::Importance);
    if (fY == Rgb(0.0)) return Rgb(0.0);
    const Rgb fZ = bsdfZ.eval(z.wi, toY, TransportMode::Radiance);
    if (fZ == Rgb(0.0)) return Rgb(0.0);
    const double g = std::abs(glm::dot(y.normal(), toY)) * std::abs(glm::dot(z.normal(), toY)) / distance2;
    if (!(g > 0)) return Rgb(0.0);
    // The far end's offset point stays on its side of its surface.
    const Ray shadow = spawnRay(z.point(), z.normal(), toY);
    const Vec3d target = offsetRayOrigin(y.point(), y.normal(), -toY);
    if (scene_.occluded(shadow, glm::length(target - shadow.origin))) return Rgb(0.0);
    const Rgb contribution = y.beta * fY * g * fZ * z.beta;

    gather(lightPath, s, cameraPath, t, d);
    const size_t iy = size_t(s - 1), iz = size_t(s);
    d.delta[iy] = d.delta[iz] = false;
    d.camera[iy] =
        toAreaDensity(bsdfZ.pdf(z.wi, toY, TransportMode::Radiance), z.point(), y.point(), y.normal());
    d.camera[iy - 1] =
        densityAt(bsdfY.pdf(-toY, y.wi, TransportMode::Radiance), y.point(), lightPath[size_t(s - 2)]);
    d.light[iz] =
        toAreaDensity(bsdfY.pdf(y.wi, -toY, TransportMode::Importance), y.point(), z.point(), z.normal());
    d.light[iz + 1] =
        densityAt(bsdfZ.pdf(toY, z.wi, TransportMode::Importance), z.point(), cameraPath[size_t(t - 2)]);
    lightEndDensities(lightPath, d);
    return contribution * d.weight(s);
  }

  // t = 1: y_{s-1} seen by the eye.
  void connectToEye(const std::vector<PathVertex>& lightPath, int s, PathDensities& d,
                    UnitRecorder& unit) const {
    const PathVertex& y = lightPath[size_t(s - 1)];
    if (!y.connectible()) return;
    const std::optional<CameraConnection> c = connectToCamera(scene_, y, settings_.filter);
    if (!c) return;
    gather(lightPath, s, eyeOnly_, 1, d);
    const size_t iy = size_t(s - 1);
    d.delta[iy] = false;
    d.camera[iy] = toAreaDensity(scene_.camera().directionPdf(c->cosTheta), scene_.camera().eye(), y.point(),
                                 y.normal());
    d.camera[iy - 1] = densityAt(y.hit.bsdf().pdf(c->toEye, y.wi, TransportMode::Radiance), y.point(),
                                 lightPath[size_t(s - 2)]);
    lightEndDensities(lightPath, d);
    unit.splat(c->film, c->value * d.weight(s));
  }

  // For s >= 2: x_0 is the light subpath's own start; its densities for the other kinds of
  // strategy, given x_1 = y_1 and, for the camera's, pC(x_0) as stored or just recomputed.
  void lightEndDensities(const std::vector<PathVertex>& lightPath, PathDensities& d) const {
    const PathVertex& y0 = lightPath[0];
    const PathVertex& y1 = lightPath[1];
    d.x0Camera = y0.deltaLight ? 0.0 : d.camera[0];
    const double pL1 = d.light[1];
    if (y0.atInfinity) {
      infiniteLightDensities(y0.light, y0.direction, y1, d);
    } else {
      sphereLightDensities(y0.light, y0.point(), y0.normal(), y1, d);
    }
    d.light[1] = pL1;  // as the light subpath made it (the same formula)
    if (y0.deltaLight) d.x0Camera = 0.0;
  }

  const Scene& scene_;
  const RenderSettings& settings_;
  LightEmission emission_;
  SubpathSettings camera_, light_;
  std::vector<PathVertex> eyeOnly_;  // the camera subpath of t = 1
};

}  // namespace

RenderResult renderBdpt(const Scene& scene, const RenderSettings& settings,
                        const std::function<void(double)>& progress) {
  const Bdpt bdpt(scene, settings);
  return renderWithSplats(scene, settings, progress,
                          [&](int x, int y, int s, UnitRecorder& unit) { bdpt.trace(x, y, s, unit); });
}

}  // namespace scatterlab
