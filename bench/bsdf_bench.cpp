// eval, pdf and sample per model, on a fixed stream of directions and random numbers.
// Concrete `final` types, as the renderer's templated paths will call them.
#include <benchmark/benchmark.h>

#include <vector>

#include "materials/bsdf/conductor.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/metals.h"
#include "materials/bsdf/microfacet.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"

namespace scatterlab {
namespace {

constexpr int Batch = 1024;

struct Inputs {
  std::vector<Vec3d> wi, wo;
  std::vector<Vec2d> u;
  std::vector<double> uLobe;
  Inputs() {
    CounterRng rng(1, 0);
    for (int i = 0; i < Batch; ++i) {
      wi.push_back(sampleCosineHemisphere(rng.uniform2D()));
      wo.push_back(sampleCosineHemisphere(rng.uniform2D()));
      u.push_back(rng.uniform2D());
      uLobe.push_back(rng.uniform());
    }
  }
};
const Inputs& inputs() {
  static const Inputs in;
  return in;
}

template <typename Model> void benchEval(benchmark::State& state, const Model& model) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (int i = 0; i < Batch; ++i) benchmark::DoNotOptimize(model.eval(in.wi[i], in.wo[i], TransportMode::Radiance));
  state.SetItemsProcessed(state.iterations() * Batch);
}
template <typename Model> void benchPdf(benchmark::State& state, const Model& model) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (int i = 0; i < Batch; ++i) benchmark::DoNotOptimize(model.pdf(in.wi[i], in.wo[i], TransportMode::Radiance));
  state.SetItemsProcessed(state.iterations() * Batch);
}
template <typename Model> void benchSample(benchmark::State& state, const Model& model) {
  const Inputs& in = inputs();
  for (auto _ : state)
    for (int i = 0; i < Batch; ++i)
      benchmark::DoNotOptimize(model.sample(in.wi[i], in.uLobe[i], in.u[i], TransportMode::Radiance));
  state.SetItemsProcessed(state.iterations() * Batch);
}

const LambertianBsdf& lambertian() {
  static const LambertianBsdf m(Rgb(0.8));
  return m;
}
template <template <typename> class Distribution>
const MicrofacetConductorBsdf<Distribution<double>>& conductor(MicrofacetSampling sampling) {
  static const MetalIor* gold = findMetal("Au");
  static const MicrofacetConductorBsdf<Distribution<double>> visible(Distribution<double>(0.3, 0.1), gold->eta, gold->k,
                                                                     MicrofacetSampling::Visible);
  static const MicrofacetConductorBsdf<Distribution<double>> classic(Distribution<double>(0.3, 0.1), gold->eta, gold->k,
                                                                     MicrofacetSampling::Classic);
  return sampling == MicrofacetSampling::Visible ? visible : classic;
}

#define SCATTERLAB_BSDF_BENCHMARKS(name, model)                                          \
  BENCHMARK_CAPTURE(benchEval, name, model)->Unit(benchmark::kNanosecond);              \
  BENCHMARK_CAPTURE(benchPdf, name, model)->Unit(benchmark::kNanosecond);               \
  BENCHMARK_CAPTURE(benchSample, name, model)->Unit(benchmark::kNanosecond);

SCATTERLAB_BSDF_BENCHMARKS(Lambertian, lambertian())
SCATTERLAB_BSDF_BENCHMARKS(GgxVisible, conductor<GgxDistribution>(MicrofacetSampling::Visible))
SCATTERLAB_BSDF_BENCHMARKS(GgxClassic, conductor<GgxDistribution>(MicrofacetSampling::Classic))
SCATTERLAB_BSDF_BENCHMARKS(BeckmannVisible, conductor<BeckmannDistribution>(MicrofacetSampling::Visible))
SCATTERLAB_BSDF_BENCHMARKS(BeckmannClassic, conductor<BeckmannDistribution>(MicrofacetSampling::Classic))

}  // namespace
}  // namespace scatterlab
