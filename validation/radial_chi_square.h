// The 1-D chi-square test of sampled radii against a radius density (docs/validation.md section 6):
// bins equal in the distribution's CDF (edges from its quantile function, so every bin expects
// N / bins when the sampler is right), expected counts N * integral of pdf() over each bin by
// adaptive quadrature in ln r (the densities span many decades of r), and the pooling,
// statistic and p-value of chi_square.h. The expectation comes from pdf() alone: a pdf that is
// off anywhere makes observed and expected differ, whatever the edges.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "validation/cell_counts.h"
#include "validation/chi_square.h"

namespace scatterlab {

struct RadialChiSquareOptions {
  size_t sampleCount = 1'000'000;
  uint64_t seed = 1;
  double threshold = 0.01;  // per-test significance (Sidak-corrected by the caller)
  double minExpected = 5.0;
};

// bins + 1 edges: 0, quantile(k / bins) for k = 1 .. bins - 1, and infinity.
std::vector<double> equalProbabilityEdges(const std::function<double(double)>& quantile, int bins);

// integral_a^b pdf(r) dr by adaptive Simpson in ln r (relative 1e-9); b may be infinite, when
// `far` (> a) stands in for it (the caller's quantile at 1 - 1e-12); a = 0 starts at 1e-14 b,
// so an interval from 0 must end at the distribution's scale (integrateAlongQuantiles below
// integrates the whole range).
double integrateRadialDensity(const std::function<double(double)>& pdf, double a, double b, double far);

// integral_0^inf f(r) dr for an f with the scale of the distribution `quantile` describes:
// the sum over the pieces between its octiles (the last up to its 1 - 1e-12 quantile), each
// by integrateRadialDensity, so that no piece's range of ln r is set by a far-away end.
double integrateAlongQuantiles(const std::function<double(double)>& f,
                               const std::function<double(double)>& quantile);

// Expected counts per bin: N * integral of pdf.
std::vector<double> radialExpectedCounts(const std::function<double(double)>& pdf,
                                         const std::vector<double>& edges, double far, size_t sampleCount);

// `draw(CounterRng&) -> std::optional<double>` (a radius, or nothing when sampling failed);
// radii that are negative or not finite are invalid samples.
template <typename DrawFn> ChiSquareResult radialChiSquareTest(const DrawFn& draw,
                                                               const std::function<double(double)>& pdf,
                                                               const std::vector<double>& edges, double far,
                                                               const RadialChiSquareOptions& options) {
  const int bins = int(edges.size()) - 1;
  const CellCounts counts = countSamples(bins, options.sampleCount, options.seed, [&](CounterRng& rng) {
    const std::optional<double> r = draw(rng);
    if (!r) return CellDraw::failed();
    if (!(*r >= 0) || !std::isfinite(*r)) return CellDraw{-1, "radius negative or not finite"};
    const int bin = int(std::upper_bound(edges.begin(), edges.end(), *r) - edges.begin()) - 1;
    return CellDraw{std::clamp(bin, 0, bins - 1), nullptr};
  });
  Table2D observed(1, bins), expected(1, bins);
  for (int b = 0; b < bins; ++b) observed.values[size_t(b)] = double(counts.counts[size_t(b)]);
  expected.values = radialExpectedCounts(pdf, edges, far, options.sampleCount);
  ChiSquareResult r =
      chiSquareFromTables(observed, expected, options.sampleCount, options.threshold, options.minExpected);
  if (counts.invalid > 0) {
    r.passed = false;
    r.failure = std::to_string(counts.invalid) + " invalid samples, first: " + counts.firstInvalid;
  }
  return r;
}

}  // namespace scatterlab
