// The renderer's hot parts, one benchmark each, and whole paths on the peers' scene:
//   random numbers (Philox per sample stream), ray-sphere intersection, environment map
//   lookup and sampling (1024 x 512, out of cache as in a render), one BSDF sample through the
//   virtual interface against the same call on the concrete `final` type (the renderer's one
//   dispatch per path vertex), and tracePath for the four materials of the Cycles comparison
//   in the white furnace and under a map, and subsurface spheres (diffusion and random walk)
//   under the map, reported as samples and path vertices per second (one thread). bench/cycles_compare.py
//   times whole renders against Blender Cycles.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "integrator/path_tracer.h"
#include "integrator/scene_presets.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/warp.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace {

constexpr int Batch = 1024;

// A 1024 x 512 map like peers/make_envmap.py's: a sky gradient, a brown ground and a sun of
// radiance 100 and 4 degrees radius toward (0.5, -0.7, 0.5).
Image syntheticMap() {
  const int width = 1024, height = 512;
  Image map(width, height);
  const Vec3d sun = glm::normalize(Vec3d(0.5, -0.7, 0.5));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec3d w = Environment::directionFromEquirect({(x + 0.5) / width, (y + 0.5) / height});
      Rgb v = w.z >= 0 ? Rgb(0.35, 0.55, 1.0) * (0.4 + 0.6 * w.z) : Rgb(0.30, 0.25, 0.20);
      if (glm::dot(w, sun) > std::cos(radians(4.0))) v = Rgb(100.0);
      map.setRgb(x, y, v);
    }
  return map;
}

const Environment& mapEnvironment() {
  static const Environment env = Environment::fromMap(syntheticMap());
  return env;
}

void SampleStreamNumbers(benchmark::State& state) {
  uint64_t pixel = 0;
  for (auto _ : state) {
    SampleStream random(1, pixel++, 0);
    for (int i = 0; i < 8; ++i) benchmark::DoNotOptimize(random.next());
  }
  state.SetItemsProcessed(state.iterations() * 8);
}
BENCHMARK(SampleStreamNumbers);

void SphereIntersection(benchmark::State& state) {
  const Sphere sphere = presetSphere();
  std::vector<Ray> rays;
  CounterRng rng(2, 0);
  for (int i = 0; i < Batch; ++i)
    rays.push_back(
        {Vec3d(0, -4, 0), glm::normalize(Vec3d(0, 4, 0) + sampleUniformSphere(rng.uniform2D()) * 1.5)});
  for (auto _ : state)
    for (const Ray& ray : rays) benchmark::DoNotOptimize(sphere.intersect(ray, 0.0, Infinity));
  state.SetItemsProcessed(state.iterations() * Batch);
}
BENCHMARK(SphereIntersection);

void EnvironmentLookup(benchmark::State& state) {
  const Environment& env = mapEnvironment();
  std::vector<Vec3d> directions;
  CounterRng rng(3, 0);
  for (int i = 0; i < Batch; ++i) directions.push_back(sampleUniformSphere(rng.uniform2D()));
  for (auto _ : state)
    for (const Vec3d& w : directions) benchmark::DoNotOptimize(env.evalWithPdf(w));
  state.SetItemsProcessed(state.iterations() * Batch);
}
BENCHMARK(EnvironmentLookup);

void EnvironmentSampling(benchmark::State& state) {
  const Environment& env = mapEnvironment();
  std::vector<Vec2d> u;
  CounterRng rng(4, 0);
  for (int i = 0; i < Batch; ++i) u.push_back(rng.uniform2D());
  for (auto _ : state)
    for (const Vec2d& x : u) benchmark::DoNotOptimize(env.sample(x));
  state.SetItemsProcessed(state.iterations() * Batch);
}
BENCHMARK(EnvironmentSampling);

// One Lambertian sample through BsdfModel& (virtual) and through the final type (inlined).
template <bool Virtual> void LambertianSample(benchmark::State& state) {
  const LambertianBsdf model(Rgb(0.8));
  const BsdfModel& base = model;
  std::vector<Vec2d> u;
  CounterRng rng(5, 0);
  for (int i = 0; i < Batch; ++i) u.push_back(rng.uniform2D());
  const Vec3d wi = glm::normalize(Vec3d(0.3, 0.2, 0.9));
  for (auto _ : state)
    for (const Vec2d& x : u) {
      if constexpr (Virtual)
        benchmark::DoNotOptimize(base.sample(wi, 0.5, x));
      else
        benchmark::DoNotOptimize(model.sample(wi, 0.5, x));
    }
  state.SetItemsProcessed(state.iterations() * Batch);
}
BENCHMARK(LambertianSample<true>)->Name("LambertianSample/virtual");
BENCHMARK(LambertianSample<false>)->Name("LambertianSample/direct");

// The Cycles comparison's materials, as cycles_sphere.py sets them (color 1, roughness 0.3 so
// GGX alpha 0.09, IOR 1.5; Principled metallic with base colour 1 is F = 1).
const nlohmann::json& peerMaterial(int index) {
  static const std::vector<nlohmann::json> materials{
      {{"type", "lambertian"}, {"albedo", 1.0}},
      {{"type", "conductor"},
       {"distribution", "ggx"},
       {"alpha", 0.09},
       {"eta", {1, 1, 1}},
       {"k", {1e8, 1e8, 1e8}}},
      {{"type", "dielectric"}, {"eta", 1.5}},
      {{"type", "rough-dielectric"}, {"distribution", "ggx"}, {"alpha", 0.09}, {"eta", 1.5}}};
  return materials[size_t(index)];
}

// Camera samples of the 256 x 256 peers' scene, pixels in a fixed pseudo-random order.
void traceCameraSamples(benchmark::State& state, const Scene& scene) {
  const IntegratorSettings settings;
  uint64_t sample = 0, vertices = 0;
  for (auto _ : state) {
    const uint64_t pixel = (sample * 2654435761u) % (256 * 256);
    SampleStream random(1, pixel, sample++);
    const Vec2d film =
        Vec2d(double(pixel % 256) + 0.5, double(pixel / 256) + 0.5) + random.next2D() - Vec2d(0.5);
    const PathSample path = tracePath(scene, scene.camera().generateRay(film), random, settings);
    vertices += path.vertices;
    benchmark::DoNotOptimize(path.radiance);
  }
  state.SetItemsProcessed(int64_t(sample));
  state.counters["vertices/s"] = benchmark::Counter(double(vertices), benchmark::Counter::kIsRate);
}

void TracePath(benchmark::State& state) {
  const bool map = state.range(1) != 0;
  const Scene scene =
      makePresetScene(ScenePreset::MaterialSphere, makeBsdf(peerMaterial(int(state.range(0)))),
                      map ? mapEnvironment() : Environment::constant(Rgb(1.0)), 256, 256);
  traceCameraSamples(state, scene);
}
BENCHMARK(TracePath)->ArgNames({"material", "map"})->ArgsProduct({{0, 1, 2, 3}, {0, 1}});

// Subsurface spheres of 1 cm (scale 10) under the map: Jensen's Skin1 and Marble (Burley's
// profile), in diffusion mode and as the random walk (integrator/subsurface.h).
void TraceSubsurfacePath(benchmark::State& state) {
  const char* medium = state.range(0) == 0 ? "Skin1" : "Marble";
  const SubsurfaceMode mode = state.range(1) == 0 ? SubsurfaceMode::Diffusion : SubsurfaceMode::RandomWalk;
  const Scene scene =
      makePresetScene(ScenePreset::MaterialSphere,
                      makeSubsurface({{"type", "subsurface"}, {"medium", medium}, {"scale", 10.0}}), mode,
                      mapEnvironment(), 256, 256);
  traceCameraSamples(state, scene);
}
BENCHMARK(TraceSubsurfacePath)->ArgNames({"marble", "walk"})->ArgsProduct({{0, 1}, {0, 1}});

}  // namespace
}  // namespace scatterlab
