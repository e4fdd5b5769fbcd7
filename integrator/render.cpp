#include "integrator/render.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "integrator/bdpt.h"
#include "integrator/light_tracer.h"
#include "integrator/sppm.h"

namespace scatterlab {

namespace {

constexpr int TileSize = 16;

void checkSettings(const PinholeCamera& camera, const RenderSettings& settings) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("render: " + what); };
  if (camera.width() > MaxImageSide || camera.height() > MaxImageSide ||
      int64_t(camera.width()) * camera.height() > MaxImagePixels)
    fail("image larger than the limits");
  if (settings.samplesPerPixel < 1 || settings.samplesPerPixel > MaxSamplesPerPixel)
    fail("samples per pixel out of range");
  if (settings.integrator.maxDepth < 0 || settings.integrator.maxDepth > MaxPathDepth)
    fail("maximum depth out of range");
  if (settings.threads < 0) fail("negative thread count");
}

// Per-pixel accumulation: sums of the samples and of their squares shifted by the first sample
// (the "shifted data" algorithm, Chan, Golub & LeVeque 1983, "Algorithms for computing the
// sample variance", Am. Stat. 37(3)): no division per sample, and no cancellation when the
// spread is small against the mean. The order of samples is fixed, so the result does not
// depend on scheduling.
struct PixelAccumulator {
  Rgb shift{0.0}, sum{0.0}, sumSquares{0.0}, albedo{0.0};
  Vec3d normal{0.0};
  uint64_t count = 0;

  void add(const Rgb& value) {
    if (count++ == 0) shift = value;
    const Rgb d = value - shift;
    sum += d;
    sumSquares += d * d;
  }
  Rgb mean() const { return shift + sum / double(count); }
  // The unbiased sample variance divided by n: the variance of the mean.
  Rgb varianceOfMean() const {
    if (count < 2) return Rgb(0.0);
    const double n = double(count);
    return glm::max(sumSquares - sum * sum / n, Rgb(0.0)) / (n * (n - 1.0));
  }
};

}  // namespace

std::vector<std::string> integratorNames() { return {"path", "light", "bdpt", "sppm"}; }

std::optional<IntegratorKind> findIntegrator(std::string_view name) {
  if (name == "path") return IntegratorKind::Path;
  if (name == "light") return IntegratorKind::Light;
  if (name == "bdpt") return IntegratorKind::Bdpt;
  if (name == "sppm") return IntegratorKind::Sppm;
  return std::nullopt;
}

std::string toString(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Path: return "path";
    case IntegratorKind::Light: return "light";
    case IntegratorKind::Bdpt: return "bdpt";
    case IntegratorKind::Sppm: return "sppm";
  }
  return "path";
}

SampleValue classifySample(const PathSample& path) {
  return classifySample(path.invalid, {path.radiance, path.albedo});
}

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const std::function<void(double)>& progress) {
  const PinholeCamera& camera = scene.camera();
  checkSettings(camera, settings);
  if (settings.integratorKind != IntegratorKind::Path) {
    if (scene.hasSubsurface())
      throw std::invalid_argument("render: integrator \"" + toString(settings.integratorKind) +
                                  "\" cannot render subsurface materials; allowed: \"path\"");
    switch (settings.integratorKind) {
      case IntegratorKind::Light: return renderLightTracing(scene, settings, progress);
      case IntegratorKind::Bdpt: return renderBdpt(scene, settings, progress);
      case IntegratorKind::Sppm: return renderSppm(scene, settings, progress);
      case IntegratorKind::Path: break;
    }
  }
  const int width = camera.width(), height = camera.height();
  const int spp = settings.samplesPerPixel;
  RenderResult result;
  result.color = Image(width, height);
  if (settings.albedoLayer) result.albedo = Image(width, height);
  if (settings.normalLayer) result.normal = Image(width, height);
  if (settings.varianceLayer) result.variance = Image(width, height);

  const int tilesX = (width + TileSize - 1) / TileSize, tilesY = (height + TileSize - 1) / TileSize;
  const int tileCount = tilesX * tilesY;
  std::atomic<uint64_t> vertices{0}, nonFinite{0}, negative{0};
  // Progress counts pixels, reported after each row of a tile: with many samples per pixel a
  // tile takes minutes, and a log should still hear from the run every few seconds.
  std::atomic<uint64_t> pixelsDone{0};
  const double pixelCount = double(width) * double(height);

  const auto renderTile = [&](int tile) {
    const int x0 = (tile % tilesX) * TileSize, y0 = (tile / tilesX) * TileSize;
    const int x1 = std::min(x0 + TileSize, width), y1 = std::min(y0 + TileSize, height);
    RenderStatistics tileStatistics;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
        PixelAccumulator acc;
        for (int s = 0; s < spp; ++s) {
          SampleStream random(settings.seed, pixel, uint64_t(s));
          const Vec2d film = Vec2d(x + 0.5, y + 0.5) + settings.filter.sampleOffset(random);
          const PathSample path = tracePath(scene, camera.generateRay(film), random, settings.integrator);
          tileStatistics.vertices += path.vertices;
          const SampleValue value = classifySample(path);
          if (value == SampleValue::Valid) {
            acc.add(path.radiance);
            acc.albedo += path.albedo;
            acc.normal += path.normal;
          } else {
            tileStatistics.count(value);
            acc.add(Rgb(0.0));
          }
        }
        result.color.setRgb(x, y, acc.mean());
        if (settings.albedoLayer) result.albedo.setRgb(x, y, acc.albedo / double(spp));
        if (settings.normalLayer) result.normal.setRgb(x, y, acc.normal / double(spp));
        if (settings.varianceLayer) result.variance.setRgb(x, y, acc.varianceOfMean());
      }
      if (progress) progress(double(pixelsDone += uint64_t(x1 - x0)) / pixelCount);
    }
    vertices += tileStatistics.vertices;
    nonFinite += tileStatistics.nonFiniteSamples;
    negative += tileStatistics.negativeSamples;
  };

  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
      for (int tile = range.begin(); tile != range.end(); ++tile) renderTile(tile);
    });
  });
  result.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.statistics.samples = uint64_t(width) * uint64_t(height) * uint64_t(spp);
  result.statistics.vertices = vertices;
  result.statistics.nonFiniteSamples = nonFinite;
  result.statistics.negativeSamples = negative;
  return result;
}

}  // namespace scatterlab
