// One whole chi-square test as `scatterlab check` runs it: 1e6 samples, a 64 x 128 grid,
// adaptive quadrature of the pdf included. Target: GGX alpha 0.1 at wi = 60 deg in
// at most 1.0 s on the project's 2-core machine. Time is wall-clock (UseRealTime) because
// the work runs on all cores through TBB.
#include <benchmark/benchmark.h>

#include "materials/bsdf/conductor.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/metals.h"
#include "materials/bsdf/microfacet.h"
#include "validation/bsdf_check.h"
#include "validation/bsdf_sampling.h"

namespace scatterlab {
namespace {

ChiSquareOptions issueOptions() {
  ChiSquareOptions o;
  o.grid = {64, 128};
  o.sampleCount = 1'000'000;
  o.threshold = 0.01;
  o.quadrature.absoluteTolerance = 1e-3 / double(o.sampleCount);  // as the suite sets it
  return o;
}

template <typename Model>
void benchChiSquare(benchmark::State& state, const Model& model, double wiThetaDeg) {
  const ChiSquareOptions o = issueOptions();
  const Vec3d wi = directionFromDegrees(wiThetaDeg, 30);
  bool passed = true;
  for (auto _ : state) {
    const ChiSquareResult r = bsdfChiSquareTest(model, wi, o);
    passed = passed && r.passed;
    benchmark::DoNotOptimize(r.statistic);
  }
  state.counters["passed"] = passed ? 1 : 0;
}

void ChiSquareGgxAlpha01Wi60(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.1, 0.1), gold->eta,
                                                               gold->k);
  benchChiSquare(state, model, 60.0);
}
void ChiSquareGgxAlpha0001Wi0(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.001, 0.001),
                                                               gold->eta, gold->k);
  benchChiSquare(state, model, 0.0);
}
void ChiSquareBeckmannAnisotropicWi85(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<BeckmannDistribution<double>> model(BeckmannDistribution<double>(0.05, 0.8),
                                                                    gold->eta, gold->k);
  benchChiSquare(state, model, 85.0);
}
void ChiSquareLambertianWi30(benchmark::State& state) {
  benchChiSquare(state, LambertianBsdf(Rgb(0.8)), 30.0);
}

// The two halves of the test, to see where the time goes.
void ChiSquareGgxAlpha01Wi60SamplingOnly(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.1, 0.1), gold->eta,
                                                               gold->k);
  const ChiSquareOptions o = issueOptions();
  const Vec3d wi = directionFromDegrees(60, 30);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        drawSamples(o.grid, bsdfDirectionSampler(model, wi), o.sampleCount, o.seed).counts.values[0]);
}
void ChiSquareGgxAlpha01Wi60QuadratureOnly(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.1, 0.1), gold->eta,
                                                               gold->k);
  const ChiSquareOptions o = issueOptions();
  const Vec3d wi = directionFromDegrees(60, 30);
  const SampleHistogram h = drawSamples(o.grid, bsdfDirectionSampler(model, wi), o.sampleCount, o.seed);
  for (auto _ : state)
    benchmark::DoNotOptimize(integrateCells(
        o.grid, [&](const Vec3d& wo) { return model.pdf(wi, wo, TransportMode::Radiance); }, h.probes,
        o.quadrature)[0]);
}

// The whole per-angle suite (chi-square, consistency, normalisation, albedo) for comparison.
void FullCheckGgxAlpha01Wi60(benchmark::State& state) {
  const MetalIor* gold = findMetal("Au");
  const MicrofacetConductorBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.1, 0.1), gold->eta,
                                                               gold->k);
  BsdfCheckOptions o;
  o.wiThetaDeg = {60};
  o.reciprocityPairs = 0;
  for (auto _ : state) benchmark::DoNotOptimize(runBsdfChecks(model, "ggx", o).rows.size());
}

BENCHMARK(ChiSquareGgxAlpha01Wi60)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(ChiSquareGgxAlpha0001Wi0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ChiSquareBeckmannAnisotropicWi85)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ChiSquareLambertianWi30)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ChiSquareGgxAlpha01Wi60SamplingOnly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ChiSquareGgxAlpha01Wi60QuadratureOnly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(FullCheckGgxAlpha01Wi60)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace scatterlab
