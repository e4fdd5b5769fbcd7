// Stochastic progressive photon mapping (Hachisuka & Jensen 2009, "Stochastic Progressive
// Photon Mapping"; the progressive radius of Hachisuka, Ogaki & Jensen 2008).
//
// Iteration k:
//  1. Camera pass: every pixel traces one camera ray (filter offset as the path tracer's) through
//     delta and purely glossy vertices, adding emission the camera ray or a delta bounce finds
//     and, at every vertex with a lobe that is not a delta, next-event estimation (light
//     sampling alone: no BSDF-sampled ray looks for emission here). At the first vertex with a
//     diffuse lobe (or a glossy one at the last bounce) it stops: the pixel's visible point,
//     with the camera's throughput beta and the number of bounces before it.
//  2. Photon pass: photonsPerIteration light paths (subpath.h, importance transport). Every
//     photon vertex after the first (the first is direct light, counted in step 1) near a
//     visible point, within its radius r and on a surface facing the same way, adds
//     beta_photon f(wi at the visible point, photon's wi) to the pixel's flux phi and one to
//     its count M, when the path light -> ... -> visible point -> eye has at most maxDepth
//     bounces.
//  3. Radius reduction, per pixel with M > 0 (Hachisuka & Jensen 2009, eqs. 4-6 of the
//     progressive scheme): N' = N + alpha M, r' = r sqrt(N' / (N + M)),
//     tau' = (tau + beta phi) r'^2 / r^2.
// The pixel is (direct light summed) / k + tau / (k P pi r^2), P photons per iteration.
//
// Consistent: the kernel's bias falls with r^2 (the density estimate averages the irradiance
// over a disk of radius r) and r^2 ~ k^(alpha - 1) (Knaus & Zwicker 2011), so the bias vanishes
// as the variance does. Same bits for any thread count: pixels trace their own camera rays
// (SampleStream(seed, pixel, k)), photons are traced in fixed chunks (SampleStream(seed,
// photon, k, Photon)) whose deposits are added in chunk order, and the grid of visible points
// is built in pixel order.
//
// Nothing fails silently: a camera sample or a photon whose weight or value is not finite or
// negative (sample_value.h) adds nothing and is counted by kind (RenderStatistics).
#include "integrator/sppm.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "integrator/emission.h"
#include "integrator/path_tracer.h"
#include "integrator/sample_value.h"
#include "integrator/subpath.h"

namespace scatterlab {

namespace {

constexpr int PhotonsPerChunk = 4096, RowsPerTask = 4;

struct VisiblePoint {
  SurfaceInteraction hit;
  Vec3d wi{0.0};
  Rgb beta{0.0};
  int bounces = 0;  // camera bounces before it
  bool valid = false;
};

struct PixelState {
  VisiblePoint point;
  double radius = 0.0, n = 0.0;
  Rgb tau{0.0}, direct{0.0}, phi{0.0}, albedo{0.0};
  Vec3d normal{0.0};
  uint64_t m = 0;
};

// Visible points by grid cell (side = the largest radius, so a point's ball meets at most 2 x 2 x
// 2 cells), hashed into a table built by counting sort in pixel order.
class VisiblePointGrid {
 public:
  void build(const std::vector<PixelState>& pixels) {
    cell_ = 0.0;
    for (const PixelState& p : pixels)
      if (p.point.valid) cell_ = std::max(cell_, p.radius);
    const size_t table = std::max<size_t>(1, pixels.size());
    start_.assign(table + 1, 0);
    entries_.clear();
    if (!(cell_ > 0)) return;
    std::vector<std::pair<size_t, uint32_t>> keyed;
    for (size_t i = 0; i < pixels.size(); ++i) {
      const PixelState& p = pixels[i];
      if (!p.point.valid) continue;
      const Vec3d lo = (p.point.hit.point - Vec3d(p.radius)) / cell_,
                  hi = (p.point.hit.point + Vec3d(p.radius)) / cell_;
      for (int64_t z = int64_t(std::floor(lo.z)); z <= int64_t(std::floor(hi.z)); ++z)
        for (int64_t y = int64_t(std::floor(lo.y)); y <= int64_t(std::floor(hi.y)); ++y)
          for (int64_t x = int64_t(std::floor(lo.x)); x <= int64_t(std::floor(hi.x)); ++x)
            keyed.push_back({bucket(x, y, z, table), uint32_t(i)});
    }
    for (const auto& [b, index] : keyed) ++start_[b + 1];
    for (size_t b = 0; b < table; ++b) start_[b + 1] += start_[b];
    entries_.resize(keyed.size());
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (const auto& [b, index] : keyed) entries_[fill[b]++] = index;
  }

  // Calls f(pixel) for every visible point whose cell holds `p` (the caller checks distance).
  template <typename F> void forEachNear(const Vec3d& p, const F& f) const {
    if (!(cell_ > 0) || !isFinite(p)) return;
    const Vec3d c = p / cell_;
    const size_t b = bucket(int64_t(std::floor(c.x)), int64_t(std::floor(c.y)), int64_t(std::floor(c.z)),
                            start_.size() - 1);
    for (uint32_t i = start_[b]; i < start_[b + 1]; ++i) f(entries_[i]);
  }

 private:
  static size_t bucket(int64_t x, int64_t y, int64_t z, size_t table) {
    // The spatial hash of Teschner et al. 2003 ("Optimized Spatial Hashing for Collision
    // Detection of Deformable Objects").
    const uint64_t h = (uint64_t(x) * 73856093u) ^ (uint64_t(y) * 19349663u) ^ (uint64_t(z) * 83492791u);
    return size_t(h % table);
  }

  double cell_ = 0.0;
  std::vector<uint32_t> start_, entries_;
};

class Sppm {
 public:
  Sppm(const Scene& scene, const RenderSettings& settings)
      : scene_(scene),
        settings_(settings),
        emission_(scene),
        width_(scene.camera().width()),
        height_(scene.camera().height()),
        photons_(settings.sppm.photonsPerIteration > 0 ? settings.sppm.photonsPerIteration
                                                       : int64_t(width_) * height_),
        pixels_(size_t(width_) * size_t(height_)) {
    const double r0 = sppmInitialRadius(scene, settings.sppm);
    for (PixelState& p : pixels_) p.radius = r0;
  }

  RenderResult run(const std::function<void(double)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    const int iterations = settings_.samplesPerPixel;
    tbb::task_arena arena(settings_.threads > 0 ? settings_.threads : tbb::task_arena::automatic);
    const int64_t chunks = (photons_ + PhotonsPerChunk - 1) / PhotonsPerChunk;
    std::vector<std::vector<Deposit>> deposits(static_cast<size_t>(chunks));
    std::vector<RenderStatistics> chunkStatistics(static_cast<size_t>(chunks));
    for (int k = 0; k < iterations; ++k) {
      // ---- 1. Camera pass.
      std::atomic<uint64_t> vertices{0}, nonFinite{0}, negative{0};
      arena.execute([&] {
        tbb::parallel_for(0, (height_ + RowsPerTask - 1) / RowsPerTask, [&](int task) {
          RenderStatistics rows;
          for (int y = task * RowsPerTask; y < std::min(height_, (task + 1) * RowsPerTask); ++y)
            for (int x = 0; x < width_; ++x) cameraPass(x, y, k, rows);
          vertices += rows.vertices;
          nonFinite += rows.nonFiniteSamples;
          negative += rows.negativeSamples;
        });
      });
      grid_.build(pixels_);
      // ---- 2. Photon pass, chunks in parallel, deposits added in chunk order.
      arena.execute([&] {
        tbb::parallel_for(int64_t(0), chunks, [&](int64_t c) {
          photonChunk(c, k, deposits[size_t(c)], chunkStatistics[size_t(c)]);
        });
      });
      for (int64_t c = 0; c < chunks; ++c) {
        for (const Deposit& d : deposits[size_t(c)]) {
          pixels_[d.pixel].phi += d.value;
          ++pixels_[d.pixel].m;
        }
        statistics_.add(chunkStatistics[size_t(c)]);
      }
      statistics_.vertices += vertices;
      statistics_.nonFiniteSamples += nonFinite;
      statistics_.negativeSamples += negative;
      // ---- 3. Radius reduction.
      for (PixelState& p : pixels_) {
        if (p.m > 0) {
          const double n = p.n + settings_.sppm.alpha * double(p.m);
          const double radius = p.radius * std::sqrt(n / (p.n + double(p.m)));
          p.tau = (p.tau + p.point.beta * p.phi) * sqr(radius / p.radius);
          p.n = n;
          p.radius = radius;
        }
        p.phi = Rgb(0.0);
        p.m = 0;
      }
      if (progress) progress(double(k + 1) / iterations);
    }
    return finish(iterations,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }

 private:
  struct Deposit {
    uint32_t pixel;
    Rgb value;
  };

  // One pixel's camera ray of iteration `iteration`; its vertices, and the pixel's sample when
  // the film's rule drops it (sample_value.h), counted in `statistics`.
  void cameraPass(int x, int y, int iteration, RenderStatistics& statistics) {
    PixelState& state = pixels_[size_t(y) * width_ + x];
    VisiblePoint& vp = state.point;
    vp.valid = false;
    const uint64_t pixel = uint64_t(y) * uint64_t(width_) + uint64_t(x);
    SampleStream random(settings_.seed, pixel, uint64_t(iteration), StreamPart::Camera);
    const Vec2d film = Vec2d(x + 0.5, y + 0.5) + settings_.filter.sampleOffset(random);
    Ray ray = scene_.camera().generateRay(film);
    const int maxDepth = settings_.integrator.maxDepth;
    Rgb beta(1.0), direct(0.0), albedo(0.0);
    Vec3d normal(0.0);
    bool emissionCounts = true;  // a camera ray or a delta bounce: nothing sampled the light
    SampleValue invalid = SampleValue::Valid;
    for (int bounce = 0;; ++bounce) {
      const std::optional<SurfaceInteraction> hit = scene_.intersect(ray);
      if (!hit) {
        if (emissionCounts)
          direct += beta * scene_.escapedRadiance(ray.direction, [](double) { return 1.0; });
        break;
      }
      ++statistics.vertices;
      const Vec3d wi = -ray.direction;
      if (bounce == 0) normal = hit->geometry.normal;
      if (hit->light >= 0) {
        if (emissionCounts) direct += beta * scene_.emitted(*hit, wi);
        break;
      }
      if (bounce >= maxDepth) break;
      const Bsdf bsdf = hit->bsdf();
      const LobeFlags flags = bsdf.flags();
      if (hasAny(flags, LobeFlags::Diffuse | LobeFlags::Glossy) && scene_.lightCount() > 0)
        direct += beta * directLighting(scene_, *hit, bsdf, wi, random, Estimator::LightOnly, LightSet::All);
      const bool visible =
          hasAny(flags, LobeFlags::Diffuse) || (hasAny(flags, LobeFlags::Glossy) && bounce == maxDepth - 1);
      const bool sampleNeeded = !visible || (bounce == 0 && settings_.albedoLayer);
      std::optional<BsdfSample> sample;
      if (sampleNeeded) {
        const double uLobe = random.next();
        const Vec2d u = random.next2D();
        sample = bsdf.sample(wi, uLobe, u, TransportMode::Radiance);
        if (bounce == 0 && sample) albedo = sample->weight;
      }
      if (visible) {
        vp = {*hit, wi, beta, bounce, true};
        break;
      }
      if (!sample || sample->weight == Rgb(0.0)) break;
      beta *= sample->weight;
      // A weight that is not finite or negative ends the ray, and the film drops the sample (the
      // path tracer's rule, path_tracer.cpp).
      if (invalid = classifyValue(beta); invalid != SampleValue::Valid) break;
      emissionCounts = sample->isDelta();
      ray = spawnRay(hit->point, hit->geometry.normal, sample->wo);
    }
    if (const SampleValue value = classifySample(invalid, {direct, beta, albedo});
        value != SampleValue::Valid) {
      statistics.count(value);
      vp.valid = false;
      return;
    }
    state.direct += direct;
    state.albedo += albedo;
    state.normal += normal;
  }

  // The deposits of the photons of chunk `chunk`, in order; a photon the film's rule drops
  // (its walk ended on an invalid weight, or a deposit is not finite or negative) deposits
  // nothing and is counted in `statistics`, with every photon's vertices.
  void photonChunk(int64_t chunk, int iteration, std::vector<Deposit>& out,
                   RenderStatistics& statistics) const {
    thread_local std::vector<PathVertex> path;
    thread_local std::vector<Deposit> photon;
    out.clear();
    statistics = {};
    const int maxDepth = settings_.integrator.maxDepth;
    const SubpathSettings subpath{maxDepth, settings_.integrator.rouletteDepth};
    const int64_t first = chunk * PhotonsPerChunk, last = std::min(photons_, first + PhotonsPerChunk);
    for (int64_t index = first; index < last; ++index) {
      SampleStream random(settings_.seed, uint64_t(index), uint64_t(iteration), StreamPart::Photon);
      const SampleValue walk = traceLightSubpath(scene_, emission_, random, subpath, path);
      if (path.empty()) continue;
      statistics.vertices += path.size() - 1;
      if (walk != SampleValue::Valid) {
        statistics.count(walk);
        continue;
      }
      photon.clear();
      SampleValue value = SampleValue::Valid;
      for (size_t i = 2; i < path.size(); ++i) {
        const PathVertex& v = path[i];
        if (v.hit.light >= 0) continue;
        grid_.forEachNear(v.point(), [&](uint32_t pixel) {
          const PixelState& state = pixels_[pixel];
          const VisiblePoint& vp = state.point;
          if (vp.bounces + int(i) > maxDepth) return;
          const Vec3d d = v.point() - vp.hit.point;
          if (glm::dot(d, d) > state.radius * state.radius) return;
          if (glm::dot(v.normal(), vp.hit.geometry.normal) <= 0) return;
          const Rgb f = vp.hit.bsdf().eval(vp.wi, v.wi, TransportMode::Radiance);
          if (f == Rgb(0.0)) return;
          const Rgb deposit = v.beta * f;
          if (value == SampleValue::Valid) value = classifyValue(deposit);
          photon.push_back({pixel, deposit});
        });
      }
      if (value == SampleValue::Valid) {
        out.insert(out.end(), photon.begin(), photon.end());
      } else {
        statistics.count(value);
      }
    }
  }

  RenderResult finish(int iterations, double seconds) const {
    RenderResult result;
    result.color = Image(width_, height_);
    if (settings_.albedoLayer) result.albedo = Image(width_, height_);
    if (settings_.normalLayer) result.normal = Image(width_, height_);
    const double totalPhotons = double(iterations) * double(photons_);
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        const PixelState& p = pixels_[size_t(y) * width_ + x];
        const Rgb indirect = p.tau / (totalPhotons * Pi * p.radius * p.radius);
        result.color.setRgb(x, y, p.direct / double(iterations) + indirect);
        if (settings_.albedoLayer) result.albedo.setRgb(x, y, p.albedo / double(iterations));
        if (settings_.normalLayer) result.normal.setRgb(x, y, p.normal / double(iterations));
      }
    result.statistics.seconds = seconds;
    result.statistics.samples = uint64_t(width_) * uint64_t(height_) * uint64_t(iterations);
    result.statistics.vertices = statistics_.vertices;
    result.statistics.nonFiniteSamples = statistics_.nonFiniteSamples;
    result.statistics.negativeSamples = statistics_.negativeSamples;
    return result;
  }

  const Scene& scene_;
  const RenderSettings& settings_;
  LightEmission emission_;
  int width_, height_;
  int64_t photons_;
  std::vector<PixelState> pixels_;
  VisiblePointGrid grid_;
  RenderStatistics statistics_;  // vertices, and dropped camera samples and photons
};

}  // namespace

double sppmInitialRadius(const Scene& scene, const SppmSettings& settings) {
  const PinholeCamera& camera = scene.camera();
  const double distance = glm::length(scene.finiteBounds().center - camera.eye());
  return settings.initialRadiusPixels * camera.pixelAngle() * std::max(distance, 1e-3);
}

RenderResult renderSppm(const Scene& scene, const RenderSettings& settings,
                        const std::function<void(double)>& progress) {
  if (settings.varianceLayer)
    throw std::invalid_argument("render: integrator \"sppm\" has no variance layer; allowed: albedo, normal");
  if (!(settings.sppm.alpha > 0 && settings.sppm.alpha < 1) || !(settings.sppm.initialRadiusPixels > 0))
    throw std::invalid_argument("render: SPPM needs alpha in (0, 1) and an initial radius > 0");
  Sppm sppm(scene, settings);
  return sppm.run(progress);
}

}  // namespace scatterlab
