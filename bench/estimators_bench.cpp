// The four estimators (integrator/render.h) on whole renders, one thread (a TBB arena of one
// worker, which need not be the calling thread: rates are per wall-clock second): path vertices per
// second (surface hits of camera and light paths; shadow rays not counted) on the preview
// scene for a diffuse and a glass sphere, and the time each needs to bring the caustic of the
// caustic scene to 1% relative standard error (its close-up camera, causticCloseUp: every
// pixel on the caustic), from the variance of the region's mean: t x relative variance / 1e-4.
// Cycles has no BDPT; README ("Estimators") quotes these against the path tracer's.
#include <benchmark/benchmark.h>

#include "integrator/render.h"
#include "integrator/scene_presets.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace {

const IntegratorKind Kinds[] = {IntegratorKind::Path, IntegratorKind::Light, IntegratorKind::Bdpt,
                                IntegratorKind::Sppm};

RenderSettings oneThread(IntegratorKind kind, int spp, uint64_t seed) {
  RenderSettings settings;
  settings.integratorKind = kind;
  settings.samplesPerPixel = spp;
  settings.seed = seed;
  settings.threads = 1;
  settings.varianceLayer = kind != IntegratorKind::Sppm;
  return settings;
}

// The preview scene (white environment, sphere light), 48 x 36, 4 samples per pixel a run.
void EstimatorVertices(benchmark::State& state) {
  const IntegratorKind kind = Kinds[state.range(0)];
  const nlohmann::json material = state.range(1) == 0
                                      ? nlohmann::json{{"type", "lambertian"}, {"albedo", 0.8}}
                                      : nlohmann::json{{"type", "dielectric"}, {"eta", 1.5}};
  const Scene scene = makePresetScene(ScenePreset::Preview, makeBsdf(material), Environment(), 48, 36);
  uint64_t vertices = 0, samples = 0, seed = 1;
  for (auto _ : state) {
    const RenderResult r = render(scene, oneThread(kind, 4, seed++));
    vertices += r.statistics.vertices;
    samples += r.statistics.samples;
  }
  state.SetLabel(toString(kind) + (state.range(1) == 0 ? " lambertian" : " glass"));
  state.counters["vertices/s"] = benchmark::Counter(double(vertices), benchmark::Counter::kIsRate);
  state.counters["samples/s"] = benchmark::Counter(double(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(EstimatorVertices)
    ->ArgNames({"integrator", "glass"})
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The caustic's close-up, 16 x 12, under the sphere light alone: seconds to 1% relative error
// of the image's mean (every pixel on the caustic's ground; a few show the sphere's edge).
void CausticTimeToOnePercent(benchmark::State& state) {
  const IntegratorKind kind = Kinds[state.range(0)];
  Scene scene = makePresetScene(ScenePreset::Caustic, makeBsdf({{"type", "dielectric"}, {"eta", 1.5}}),
                                presetLighting(ScenePreset::Caustic, std::nullopt), 16, 12);
  scene.setCamera(causticCloseUp(16, 12));
  const int spp = kind == IntegratorKind::Bdpt ? 64 : 256;
  double seconds = 0, relativeVariance = 0;
  uint64_t seed = 1, runs = 0;
  for (auto _ : state) {
    const RenderResult r = render(scene, oneThread(kind, spp, seed++));
    double mean = 0, variance = 0;
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 16; ++x) {
        mean += luminance(r.color.rgb(x, y)) / 192.0;
        variance += luminance(r.variance.rgb(x, y)) / (192.0 * 192.0);
      }
    seconds += r.statistics.seconds;
    relativeVariance += variance / (mean * mean);
    ++runs;
  }
  state.SetLabel(toString(kind));
  state.counters["seconds_to_1%"] = seconds * relativeVariance / double(runs * runs) / 1e-4;
}
BENCHMARK(CausticTimeToOnePercent)
    ->ArgName("integrator")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace scatterlab
