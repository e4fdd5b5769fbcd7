// Measured BRDFs: loading a MERL file into a TabulatedBrdf (target <= 0.3 s: read, fill rule,
// sampler tables), and generating a table (`scatterlab synth`, single thread). Eval, pdf and
// sample are in bsdf_bench (MeasuredChrome).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "materials/bsdf/cook_torrance.h"
#include "materials/bsdf/lambertian.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/tabulated_brdf.h"

namespace scatterlab {
namespace {

const LambertianBsdf& diffuse() {
  static const LambertianBsdf m(Rgb(0.0886, 0.0602, 0.0299));
  return m;
}
const NganCookTorranceBsdf& lobe() {  // alum-bronze's Cook-Torrance fit
  static const NganCookTorranceBsdf m(Rgb(0.118, 0.0698, 0.0371), 0.203, 0.0367);
  return m;
}

// A MERL file in the temporary directory, written once and removed at exit.
struct TemporaryMerlFile {
  std::filesystem::path path = std::filesystem::temp_directory_path() / "scatterlab-measured-bench.binary";
  TemporaryMerlFile() { writeMerl(path, MeasurementSynthesizer({&diffuse(), &lobe()}, {}).synthesize()); }
  ~TemporaryMerlFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};
const std::filesystem::path& merlFile() {
  static const TemporaryMerlFile file;
  return file.path;
}

void readMerlFile(benchmark::State& state) {
  merlFile();  // written before timing
  for (auto _ : state) benchmark::DoNotOptimize(readMerl(merlFile()));
}
void loadTabulatedBrdf(benchmark::State& state) {
  merlFile();
  for (auto _ : state) {
    const TabulatedBrdf brdf(readMerl(merlFile()));
    benchmark::DoNotOptimize(brdf.missingCells());
  }
}
void synthesiseTable(benchmark::State& state) {
  MeasurementPerturbation noisy;
  noisy.logSigma = 0.05;
  const MeasurementSynthesizer synthesizer({&diffuse(), &lobe()}, noisy);
  for (auto _ : state) benchmark::DoNotOptimize(synthesizer.synthesize());
}

BENCHMARK(readMerlFile)->Unit(benchmark::kMillisecond);
BENCHMARK(loadTabulatedBrdf)->Unit(benchmark::kMillisecond);
BENCHMARK(synthesiseTable)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scatterlab
