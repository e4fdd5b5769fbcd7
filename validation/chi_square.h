// Chi-square goodness of fit of a direction sampler against its claimed density
// (docs/validation.md section 1; the method of Mitsuba 0.6 / pbrt-v3, with adaptive quadrature
// for expected counts, delta-lobe support and hard failures for invalid samples).
//
// The pieces are separate so that a suite can reuse one pass of sampling and one pass of
// quadrature for several checks:
//   drawSamples()        histogram of N samples (counter-based RNG, TBB, thread-count
//                        independent: integer accumulation only)
//   integrateCells()     per-cell integral of any integrand (pdf, or pdf and f|cos| together)
//   chiSquareFromTables() pooling, statistic, dof, p-value
//   sphericalChiSquareTest() all three for a sampler + pdf.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "materials/core/quadrature.h"
#include "materials/core/rng.h"
#include "validation/spherical_grid.h"

namespace scatterlab {

// What a sampler under test returns for one draw.
struct DirectionSample {
  Vec3d w;
  double pdf = 0.0;  // density per solid angle, or discrete probability if isDelta
  bool isDelta = false;
  Rgb weight{1.0};                // carried along for energy checks (BSDF: f |cos| / pdf)
  const char* invalid = nullptr;  // set by an adaptor when the draw broke a rule (NaN weight...)
};

// A discrete direction produced by a delta lobe, with the probability the sampler claims.
struct DeltaDirection {
  Vec3d w;
  int cell = 0;
  double probability = 0.0;
  Rgb weight{0.0};
};

struct SampleHistogram {
  Table2D counts;             // samples per cell (continuous and delta)
  std::vector<Vec2d> probes;  // per cell: centroid (cos theta, phi) of its continuous samples, or NaN
  size_t sampleCount = 0;
  size_t failedSamples = 0;   // sampler returned nothing (legal: reduces the pdf's mass)
  size_t invalidSamples = 0;  // broke a rule: always a test failure
  size_t deltaSamples = 0;
  std::string firstInvalid;            // description of the lowest-index invalid sample
  std::vector<DeltaDirection> deltas;  // distinct delta directions, sorted by cell
  std::string deltaMismatch;           // one delta direction reported with two probabilities
};

// Two delta samples are the same direction if they agree to this (they come from the same
// closed-form reflection/refraction of the same wi).
inline constexpr double DeltaDirectionTolerance = 1e-9;
// A sampled direction's |w| must be 1 within this to count as a direction (tighter than the
// 1e-5 that materials/bsdf/direction_pairs.h allows a direction typed by a person: a sampler
// normalises its output).
inline constexpr double SampledDirectionUnitLengthTolerance = 1e-6;

namespace detail {
// Coordinates are accumulated in 32.32 fixed point so that sums are exact integers and
// the centroid does not depend on how TBB split the work.
inline constexpr double FixedPointScale = 4294967296.0;
struct HistogramAccumulator {
  std::vector<uint64_t> counts;
  std::vector<int64_t> sumCos, sumPhi;
  std::vector<uint64_t> continuousCounts;
  size_t failed = 0, invalid = 0, delta = 0;
  size_t firstInvalidIndex = SIZE_MAX;
  std::string firstInvalid;
  std::vector<DeltaDirection> deltas;
  std::string deltaMismatch;
  explicit HistogramAccumulator(int cells)
      : counts(cells, 0), sumCos(cells, 0), sumPhi(cells, 0), continuousCounts(cells, 0) {}
};
void addDelta(std::vector<DeltaDirection>& deltas, const DeltaDirection& d, std::string& mismatch);
const char* checkDirectionSample(const DirectionSample& s);
SampleHistogram mergeHistograms(const SphericalGrid& grid, size_t n,
                                tbb::enumerable_thread_specific<HistogramAccumulator>& parts);
}  // namespace detail

// Draws N samples; sample i uses CounterRng(seed, i), so the histogram is the same for any
// number of threads. `draw(CounterRng&) -> std::optional<DirectionSample>`.
template <typename DrawFn>
SampleHistogram drawSamples(const SphericalGrid& grid, const DrawFn& draw, size_t n, uint64_t seed) {
  tbb::enumerable_thread_specific<detail::HistogramAccumulator> parts(
      [&] { return detail::HistogramAccumulator(grid.cellCount()); });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
    auto& acc = parts.local();
    for (size_t i = range.begin(); i != range.end(); ++i) {
      CounterRng rng(seed, i);
      const std::optional<DirectionSample> s = draw(rng);
      if (!s) {
        ++acc.failed;
        continue;
      }
      if (const char* why = s->invalid ? s->invalid : detail::checkDirectionSample(*s)) {
        ++acc.invalid;
        if (i < acc.firstInvalidIndex) {
          acc.firstInvalidIndex = i;
          acc.firstInvalid = std::string(why) + " (sample " + std::to_string(i) + ")";
        }
        continue;
      }
      const int cell = grid.cellIndex(s->w);
      ++acc.counts[cell];
      if (s->isDelta) {
        ++acc.delta;
        detail::addDelta(acc.deltas, DeltaDirection{s->w, cell, s->pdf, s->weight}, acc.deltaMismatch);
      } else {
        ++acc.continuousCounts[cell];
        acc.sumCos[cell] += int64_t(std::llround(s->w.z * detail::FixedPointScale));
        acc.sumPhi[cell] += int64_t(std::llround(std::atan2(s->w.y, s->w.x) * detail::FixedPointScale));
      }
    }
  });
  return detail::mergeHistograms(grid, n, parts);
}

inline double scalarPart(double v) { return v; }
template <int N> double scalarPart(const glm::vec<N, double>& v) { return v[0]; }

// The pieces a cell is integrated over, rectangles in (cos theta, phi), in the order their
// integrals are summed: the cell cut at the horizon and at its probe (the centroid of the samples
// that landed in it), so that a lobe narrower than the quadrature's first grid, but where the
// sampler put samples, is found by the quadrature's initial points. Probes only steer where the
// quadrature looks; the values are integrals of the integrand alone.
//
// At a pole, cos(theta) squares the lobe's width: a lobe of angular radius r is r^2 / 2 wide
// there (a rough dielectric's refracted lobe at normal incidence, (1 - 1/eta) times narrower
// than its facets, reaches 1e-9), below the finest step adaptive Simpson takes in a whole
// cell. A pole cell whose probe lies at d from the pole is therefore also cut at 4 d, 16 d,
// 64 d, ... from it, so that the pieces grow geometrically from the lobe's scale.
struct CellPiece {
  double cosLo, cosHi, phiLo, phiHi;
};
struct CellPieces {
  static constexpr int MaxCosCuts = 40;  // edges, horizon, probe and up to 35 pole cuts (4^35 >> 1/ulp)
  CellPiece pieces[2 * (MaxCosCuts - 1)];
  int count = 0;
};
inline CellPieces cellPieces(const SphericalGrid& grid, int cell, const Vec2d& probe) {
  constexpr int MaxCosCuts = CellPieces::MaxCosCuts;
  const int r = cell / grid.phiBins, c = cell % grid.phiBins;
  double cosCuts[MaxCosCuts], phiCuts[3] = {grid.phiEdge(c), 0, 0};
  int nCos = 0, nPhi = 1;
  const double cosLo = grid.cosThetaEdge(r), cosHi = grid.cosThetaEdge(r + 1), phiHi = grid.phiEdge(c + 1);
  cosCuts[nCos++] = cosLo;
  if (cosLo < 0.0 && 0.0 < cosHi) cosCuts[nCos++] = 0.0;
  if (cosLo < probe.x && probe.x < cosHi && probe.x != 0.0) {
    cosCuts[nCos++] = probe.x;
    for (const double pole : {-1.0, 1.0}) {
      if (pole != (pole > 0 ? cosHi : cosLo)) continue;  // the cell does not reach this pole
      const double toPole = std::abs(pole - probe.x);
      for (double step = 4 * toPole; step < cosHi - cosLo && nCos < MaxCosCuts - 1; step *= 4)
        cosCuts[nCos++] = pole > 0 ? pole - step : pole + step;
    }
  }
  cosCuts[nCos++] = cosHi;
  std::sort(cosCuts, cosCuts + nCos);
  if (phiCuts[0] < probe.y && probe.y < phiHi) phiCuts[nPhi++] = probe.y;
  phiCuts[nPhi++] = phiHi;
  CellPieces result;
  for (int i = 0; i + 1 < nCos; ++i)
    for (int j = 0; j + 1 < nPhi; ++j)
      result.pieces[result.count++] = {cosCuts[i], cosCuts[i + 1], phiCuts[j], phiCuts[j + 1]};
  return result;
}

// Integral of integrand(w) over each cell, w the unit direction, as the sum of the integrals
// over its pieces (cellPieces; `probes` empty: no probes). Cells are independent, so this is
// deterministic. Returns the integrals and, per cell, the quadrature's own error estimate
// (quadrature.h QuadratureEstimate), summed over the cell's pieces.
// integrateCellsInBatches (batched_quadrature.h) computes the same numbers, asking for the
// integrand's values a whole level of the quadrature at a time.
template <typename V> struct CellIntegrals {
  std::vector<V> values, errors;  // per cell: the integral, the quadrature's error estimate
  explicit CellIntegrals(int cellCount)
      : values(size_t(cellCount), V(0.0)), errors(size_t(cellCount), V(0.0)) {}
};

template <typename Integrand>
auto integrateCellsWithError(const SphericalGrid& grid, const Integrand& integrand,
                             const std::vector<Vec2d>& probes, const QuadratureOptions& options) {
  using V = decltype(integrand(Vec3d(0, 0, 1)));
  CellIntegrals<V> result(grid.cellCount());
  tbb::parallel_for(
      tbb::blocked_range<int>(0, grid.cellCount(), 16), [&](const tbb::blocked_range<int>& range) {
        for (int cell = range.begin(); cell != range.end(); ++cell) {
          const CellPieces pieces = cellPieces(grid, cell, probes.empty() ? Vec2d(NAN) : probes[cell]);
          V sum = V(0.0), error = V(0.0);
          for (int k = 0; k < pieces.count; ++k) {
            const CellPiece& p = pieces.pieces[k];
            const QuadratureEstimate<V> piece = adaptiveSimpson2DEstimate(
                [&](double cosTheta, double phi) {
                  return integrand(SphericalGrid::direction(cosTheta, phi));
                },
                p.cosLo, p.cosHi, p.phiLo, p.phiHi, options);
            sum = sum + piece.value;
            error = error + piece.error;
          }
          result.values[cell] = sum;
          result.errors[cell] = error;
        }
      });
  return result;
}

template <typename Integrand> auto integrateCells(const SphericalGrid& grid, const Integrand& integrand,
                                                  const std::vector<Vec2d>& probes,
                                                  const QuadratureOptions& options) {
  return integrateCellsWithError(grid, integrand, probes, options).values;
}

// A chi-square test with no degrees of freedom (every sample in one scored cell) has no
// distribution: it tests the count alone, |O - E| / sqrt(E) <= CountSigmas (a Gaussian beyond
// 5 sigma has probability 6e-7).
inline constexpr double CountSigmas = 5.0;

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  // p = Q(dof / 2, chi2 / 2); NaN when dof = 0, where no p-value exists (hasPValue()).
  double pValue = 0.0;
  double threshold = 0.0;  // significance level the p-value is compared with
  bool passed = false;
  std::string failure;  // set when rejected for a reason other than the p-value
  int pooledCells = 0;  // cells merged into the low-expectation pool
  double countZ = 0.0;  // dof = 0 only: |O - E| / sqrt(E) of the one scored cell
  Table2D observed, expected;

  bool hasPValue() const { return dof > 0; }
};

// Pools cells with expected < minExpected into one cell (sorted by expectation; a pool that
// stays below minExpected is merged with the next cell), rejects at once when any sample lies
// in a cell whose expectation is 0, and computes chi2 = sum (O - E)^2 / E,
// dof = scored cells - 1, p = Q(dof / 2, chi2 / 2). With dof = 0 there is no p-value: the
// one cell's count is tested against CountSigmas instead.
ChiSquareResult chiSquareFromTables(const Table2D& observed, const Table2D& expected, size_t sampleCount,
                                    double threshold, double minExpected = 5.0);

// Per-test significance for a family of m tests at family-wise level alpha (Sidak):
// 1 - (1 - alpha)^(1/m).
double sidakSignificance(double alpha, int testCount);

struct ChiSquareOptions {
  SphericalGrid grid;
  size_t sampleCount = 1'000'000;
  uint64_t seed = 1;
  double threshold = 0.01;  // per-test significance (already Sidak-corrected by the caller)
  double minExpected = 5.0;
  QuadratureOptions quadrature;
};

// Expected counts = N * (integral of pdf over the cell) + N * P for each delta direction.
Table2D expectedCounts(const SphericalGrid& grid, const std::vector<double>& pdfIntegrals,
                       const std::vector<DeltaDirection>& deltas, size_t sampleCount);

// The verdict for a histogram and the per-cell pdf integrals: chiSquareFromTables, plus the
// histogram's hard failures (invalid samples, one delta direction with two probabilities),
// which reject whatever the statistic says.
ChiSquareResult chiSquareVerdict(const SampleHistogram& histogram, const std::vector<double>& pdfIntegrals,
                                 const SphericalGrid& grid, size_t sampleCount, double threshold,
                                 double minExpected = 5.0);

// The whole test for `draw(CounterRng&) -> optional<DirectionSample>` against `pdf(w)`.
template <typename DrawFn, typename PdfFn>
ChiSquareResult sphericalChiSquareTest(const DrawFn& draw, const PdfFn& pdf,
                                       const ChiSquareOptions& options) {
  const SampleHistogram histogram = drawSamples(options.grid, draw, options.sampleCount, options.seed);
  const std::vector<double> integrals =
      integrateCells(options.grid, pdf, histogram.probes, options.quadrature);
  return chiSquareVerdict(histogram, integrals, options.grid, options.sampleCount, options.threshold,
                          options.minExpected);
}

}  // namespace scatterlab
