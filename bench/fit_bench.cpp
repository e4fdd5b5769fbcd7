// Fitting speed. The target: a Lambert + GGX fit (white GGX conductor lobe with a
// fitted RGB scale, `--model lambertian+{"type":"conductor","eta":1,"k":1e8}`) to one full MERL-layout table,
// 1,458,000 cells x 3 channels, in at most 10 s on the project's 2-core machine: FitLambertGgxFullTable
// (grid, multi-start on a stratified subset, refinement on every usable cell, covariance).
// The table is alum-bronze's published Cook-Torrance line (a sharp metal highlight), so the
// fit is a real cross-model fit, not a recovery. The pieces: reading the cells, one cost
// evaluation and one evaluation of the normal equations (the Jacobian's part) over the whole
// table.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include "fitting/brdf_fit.h"
#include "fitting/least_squares.h"
#include "materials/bsdf/cook_torrance.h"
#include "materials/bsdf/lambertian.h"
#include "materials/measured/measurement_synthesis.h"

namespace scatterlab::fitting {
namespace {

const MerlTable& alumBronze() {
  static const MerlTable table = [] {
    const LambertianBsdf diffuse(Rgb(0.0886, 0.0602, 0.0299));
    const NganCookTorranceBsdf lobe(Rgb(0.118, 0.0698, 0.0371), 0.203, 0.0367);
    return MeasurementSynthesizer({&diffuse, &lobe}, {}).synthesize();
  }();
  return table;
}

const BrdfSamples& alumBronzeSamples() {
  static const BrdfSamples samples = samplesFromMerl(alumBronze());
  return samples;
}

const FitModel& lambertGgx() {
  static const FitModel model(parseModelSpec(std::string("lambertian+") + WhiteConductorSpec), false);
  return model;
}

// Near the optimum, where the refinement spends its evaluations.
std::vector<double> nearOptimum() { return {0.0, 0.0, 0.0, 0.055, 0.032, 0.017, 0.0162}; }

void samplesFromTable(benchmark::State& state) {
  alumBronze();
  for (auto _ : state) benchmark::DoNotOptimize(samplesFromMerl(alumBronze()).size());
}

void costOfFullTable(benchmark::State& state) {
  const MetricSamples samples(alumBronzeSamples(), Metric::Ngan);
  const BrdfLeastSquares problem(lambertGgx(), samples, nullptr, int(state.range(0)));
  const std::vector<double> x = nearOptimum();
  for (auto _ : state) benchmark::DoNotOptimize(problem.cost(x.data()));
  state.counters["cells"] = double(alumBronzeSamples().size());
}

void normalEquationsOfFullTable(benchmark::State& state) {
  const MetricSamples samples(alumBronzeSamples(), Metric::Ngan);
  const BrdfLeastSquares problem(lambertGgx(), samples, nullptr, int(state.range(0)));
  const std::vector<double> x = nearOptimum();
  for (auto _ : state) benchmark::DoNotOptimize(problem.normalEquations(x.data()).cost);
}

// CPU seconds of every thread of the process so far: on a shared machine the wall time
// depends on the other load, the CPU time does not (wall on an idle machine with T cores is
// about the larger of the main thread's time and this over T).
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void fitLambertGgxFullTable(benchmark::State& state) {
  alumBronzeSamples();
  FitOptions options;
  options.metric = Metric::Ngan;
  options.threads = int(state.range(0));
  FitResult result;
  double cpu = 0;
  for (auto _ : state) {
    // The whole command's work after reading the file: the usable cells, then the fit.
    const double before = processCpuSeconds();
    const BrdfSamples samples = samplesFromMerl(alumBronze());
    result = fitBrdf(lambertGgx(), samples, options);
    cpu += processCpuSeconds() - before;
  }
  state.counters["refine_iterations"] = result.final.iterations;
  state.counters["alpha"] = result.x.back();
  state.counters["converged"] = result.final.converged;
  state.counters["process_cpu_s"] = cpu / double(state.iterations());
}

BENCHMARK(samplesFromTable)->Unit(benchmark::kMillisecond);
BENCHMARK(costOfFullTable)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(normalEquationsOfFullTable)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(fitLambertGgxFullTable)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace scatterlab::fitting
