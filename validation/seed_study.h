// The size of the chi-square test, measured (docs/validation.md section 1, "Size"): how often a
// correct sampler fails over many seeds, instead of a lucky seed. One correct sampler is tested with many
// seeds at an unadjusted significance alpha; the rejection rate must be Binomial(runs, alpha) and the
// p-values uniform. A test whose rate is far above alpha rejects correct models (its expected counts are
// wrong: quadrature, pooling, delta handling); far below, it has lost power.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "validation/chi_square.h"

namespace scatterlab {

struct SeedStudyResult {
  int runs = 0;
  int rejected = 0;  // runs with p < alpha
  double alpha = 0.0;
  std::vector<double> pValues;
  // Kolmogorov-Smirnov distance of the p-values from U(0, 1).
  double ksDistance() const {
    std::vector<double> p = pValues;
    std::sort(p.begin(), p.end());
    const double n = double(p.size());
    double d = 0;
    for (size_t i = 0; i < p.size(); ++i)
      d = std::max({d, std::abs(p[i] - double(i) / n), std::abs(p[i] - double(i + 1) / n)});
    return d;
  }
  // Standard deviations of the rejection count from its binomial mean runs * alpha.
  double rejectionZ() const {
    const double mean = runs * alpha, sd = std::sqrt(runs * alpha * (1 - alpha));
    return (rejected - mean) / sd;
  }
};

// `runs` chi-square tests of `draw` against `pdf`, seeds seedBase, seedBase + 1, ...; the
// expected counts are integrated once (they depend on the pdf alone), guided by the probes
// of the first run's histogram so that narrow lobes are found.
template <typename DrawFn, typename PdfFn>
SeedStudyResult repeatedSeedStudy(const DrawFn& draw, const PdfFn& pdf, const SphericalGrid& grid,
                                  size_t samples, int runs, double alpha, uint64_t seedBase) {
  SeedStudyResult study;
  study.runs = runs;
  study.alpha = alpha;
  const SampleHistogram first = drawSamples(grid, draw, samples, seedBase);
  const std::vector<double> integrals = integrateCells(grid, pdf, first.probes, QuadratureOptions{});
  for (int run = 0; run < runs; ++run) {
    const SampleHistogram h = run == 0 ? first : drawSamples(grid, draw, samples, seedBase + uint64_t(run));
    const ChiSquareResult r = chiSquareVerdict(h, integrals, grid, samples, alpha);
    study.rejected += r.passed ? 0 : 1;
    study.pValues.push_back(r.pValue);
  }
  return study;
}

}  // namespace scatterlab
