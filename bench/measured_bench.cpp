// Measured BRDFs: loading a MERL file into a TabulatedBrdf (target <= 0.3 s: read, fill rule,
// sampler tables), generating a table (`scatterlab synth`, single thread), and loading an RGL
// file (target <= 50 ms: read, validate, build the warps). Eval, pdf and sample are in
// bsdf_bench (MeasuredChrome, Rgl*).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "materials/bsdf/cook_torrance.h"
#include "materials/bsdf/lambertian.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/rgl_brdf.h"
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

// Argument: 0 the glossy vinyl, 1 the felt (both 659 kB).
void loadRglFile(benchmark::State& state) {
  const char* name = state.range(0) == 0 ? "cc_ibiza_sunset_rgb.bsdf" : "acrylic_felt_green_rgb.bsdf";
  const std::filesystem::path path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "rgl" / name;
  for (auto _ : state) benchmark::DoNotOptimize(readRglBrdf(path));
}

BENCHMARK(readMerlFile)->Unit(benchmark::kMillisecond);
BENCHMARK(loadRglFile)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(loadTabulatedBrdf)->Unit(benchmark::kMillisecond);
BENCHMARK(synthesiseTable)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scatterlab
