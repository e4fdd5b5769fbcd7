// Subsurface speed: profile evaluation and radius sampling per model (Skin1), probe sampling
// with its exact pdf, random-walk paths per second (single thread; the walk scales with TBB),
// and the cost of a photon beam diffusion table.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "materials/bssrdf/beam_diffusion_table.h"
#include "materials/bssrdf/measured_media.h"
#include "materials/bssrdf/probe_sampling.h"
#include "materials/bssrdf/subsurface_material.h"
#include "materials/core/rng.h"
#include "validation/half_space_reference.h"

namespace scatterlab {
namespace {

constexpr int Batch = 1024;

const RadialProfile& skin1(ProfileModel model) {
  static std::shared_ptr<const RadialProfile> profiles[4];
  auto& p = profiles[int(model)];
  if (!p) {
    const MeasuredMedium* m = findMeasuredMedium("Skin1");
    ScatteringMedium medium;
    medium.sigmaS = m->sigmaSPrime;
    medium.sigmaA = m->sigmaA;
    medium.eta = m->eta;
    p = makeProfile(model, medium, BurleyFit::Searchlight);
  }
  return *p;
}

std::vector<double> uniforms() {
  std::vector<double> u;
  CounterRng rng(1, 0);
  for (int i = 0; i < Batch; ++i) u.push_back(rng.uniform());
  return u;
}

void BM_ProfileEval(benchmark::State& state) {
  const RadialProfile& profile = skin1(ProfileModel(state.range(0)));
  std::vector<double> radii;
  for (double u : uniforms()) radii.push_back(profile.sampleRadius(1, u));
  for (auto _ : state)
    for (double r : radii) benchmark::DoNotOptimize(profile.eval(r));
  state.SetItemsProcessed(state.iterations() * Batch);
  state.SetLabel(profile.name());
}
BENCHMARK(BM_ProfileEval)->DenseRange(0, 3);

void BM_RadiusSample(benchmark::State& state) {
  const RadialProfile& profile = skin1(ProfileModel(state.range(0)));
  const std::vector<double> u = uniforms();
  for (auto _ : state)
    for (int i = 0; i < Batch; ++i) benchmark::DoNotOptimize(profile.sampleRadius(i % 3, u[size_t(i)]));
  state.SetItemsProcessed(state.iterations() * Batch);
  state.SetLabel(profile.name());
}
BENCHMARK(BM_RadiusSample)->DenseRange(0, 3);

// A probe chord and the exact multi-axis pdf of a point at its radius (what a renderer pays per
// found exit point).
void BM_ProbeSampleAndPdf(benchmark::State& state) {
  const RadialProfile& profile = skin1(ProfileModel(state.range(0)));
  const ProbeSampler sampler(profile);
  const Framed frame = Framed::fromNormal(glm::normalize(Vec3d(0.3, 0.4, 0.866)));
  const std::vector<double> u = uniforms();
  for (auto _ : state)
    for (int i = 0; i + 2 < Batch; ++i) {
      const ProbeSegment s =
          sampler.sample(frame, Vec3d(0.0), u[size_t(i)], {u[size_t(i) + 1], u[size_t(i) + 2]});
      benchmark::DoNotOptimize(sampler.pdf(frame, Vec3d(0.0), 0.5 * (s.start + s.end), frame.n));
    }
  state.SetItemsProcessed(state.iterations() * (Batch - 2));
  state.SetLabel(profile.name());
}
BENCHMARK(BM_ProbeSampleAndPdf)->DenseRange(0, 3);

// Paths per second of one thread; args: albedo x 1e5, eta x 100 (the searchlight, g = 0). The
// last is Burley's A ~ 0.99 end of the shape-factor fit (c = 1 - 1e-5, index-matched).
void BM_WalkPaths(benchmark::State& state) {
  HalfSpaceWalkSettings s;
  s.albedo = state.range(0) / 1e5;
  s.eta = state.range(1) / 100.0;
  uint64_t path = 0, events = 0;
  for (auto _ : state) {
    CounterRng rng(1, path++);
    const WalkPath p = traceHalfSpacePath(s, rng);
    events += p.scatteringEvents;
    benchmark::DoNotOptimize(p.exitRadius);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["events_per_path"] = double(events) / double(state.iterations());
  state.counters["events_per_s"] = benchmark::Counter(double(events), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WalkPaths)
    ->Args({80000, 100})
    ->Args({99000, 100})
    ->Args({99900, 100})
    ->Args({99000, 130})
    ->Args({99999, 100});

// One photon beam diffusion table (100 albedos x 64 radii; TBB over rows).
void BM_BeamDiffusionTable(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(BeamDiffusionTable(0.0, 1.3).effectiveAlbedo(50));
}
BENCHMARK(BM_BeamDiffusionTable)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
}  // namespace scatterlab
