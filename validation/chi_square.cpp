#include "validation/chi_square.h"

#include <limits>
#include <numeric>
#include <sstream>

#include <Eigen/Core>
#include <unsupported/Eigen/SpecialFunctions>

namespace scatterlab {
namespace detail {

const char* checkDirectionSample(const DirectionSample& s) {
  if (!isFinite(s.w)) return "non-finite direction";
  if (std::abs(glm::length(s.w) - 1.0) > SampledDirectionUnitLengthTolerance)
    return "direction is not unit length";
  if (!std::isfinite(s.pdf) || s.pdf <= 0.0) return "pdf of a drawn sample is not finite and positive";
  if (s.isDelta && s.pdf > 1.0 + 1e-12) return "discrete probability of a delta sample exceeds 1";
  return nullptr;
}

void addDelta(std::vector<DeltaDirection>& deltas, const DeltaDirection& d, std::string& mismatch) {
  for (const DeltaDirection& known : deltas) {
    if (glm::length(known.w - d.w) > DeltaDirectionTolerance) continue;
    if (mismatch.empty() && relativeDifference(known.probability, d.probability) > 1e-9) {
      std::ostringstream msg;
      msg << "one delta direction sampled with two probabilities: " << known.probability << " and "
          << d.probability;
      mismatch = msg.str();
    }
    return;
  }
  deltas.push_back(d);
}

SampleHistogram mergeHistograms(const SphericalGrid& grid, size_t n,
                                tbb::enumerable_thread_specific<HistogramAccumulator>& parts) {
  const int cells = grid.cellCount();
  HistogramAccumulator total(cells);
  for (HistogramAccumulator& part : parts) {
    for (int i = 0; i < cells; ++i) {
      total.counts[i] += part.counts[i];
      total.continuousCounts[i] += part.continuousCounts[i];
      total.sumCos[i] += part.sumCos[i];
      total.sumPhi[i] += part.sumPhi[i];
    }
    total.failed += part.failed;
    total.invalid += part.invalid;
    total.delta += part.delta;
    if (part.firstInvalidIndex < total.firstInvalidIndex) {
      total.firstInvalidIndex = part.firstInvalidIndex;
      total.firstInvalid = part.firstInvalid;
    }
    for (const DeltaDirection& d : part.deltas) addDelta(total.deltas, d, total.deltaMismatch);
    if (total.deltaMismatch.empty()) total.deltaMismatch = part.deltaMismatch;
  }
  // Thread-specific parts come in no fixed order: sort what order could change.
  std::sort(total.deltas.begin(), total.deltas.end(), [](const DeltaDirection& a, const DeltaDirection& b) {
    if (a.cell != b.cell) return a.cell < b.cell;
    if (a.w.x != b.w.x) return a.w.x < b.w.x;
    if (a.w.y != b.w.y) return a.w.y < b.w.y;
    return a.w.z < b.w.z;
  });

  SampleHistogram h;
  h.counts = Table2D(grid.thetaBins, grid.phiBins);
  h.probes.assign(cells, Vec2d(NAN));
  for (int i = 0; i < cells; ++i) {
    h.counts.values[i] = double(total.counts[i]);
    if (const uint64_t c = total.continuousCounts[i]) {
      h.probes[i] =
          Vec2d(double(total.sumCos[i]) / double(c), double(total.sumPhi[i]) / double(c)) / FixedPointScale;
    }
  }
  h.sampleCount = n;
  h.failedSamples = total.failed;
  h.invalidSamples = total.invalid;
  h.deltaSamples = total.delta;
  h.firstInvalid = total.firstInvalid;
  h.deltas = std::move(total.deltas);
  h.deltaMismatch = total.deltaMismatch;
  return h;
}

}  // namespace detail

Table2D expectedCounts(const SphericalGrid& grid, const std::vector<double>& pdfIntegrals,
                       const std::vector<DeltaDirection>& deltas, size_t sampleCount) {
  Table2D expected(grid.thetaBins, grid.phiBins);
  for (int i = 0; i < grid.cellCount(); ++i) expected.values[i] = pdfIntegrals[i] * double(sampleCount);
  for (const DeltaDirection& d : deltas) expected.values[d.cell] += d.probability * double(sampleCount);
  return expected;
}

ChiSquareResult chiSquareFromTables(const Table2D& observed, const Table2D& expected, size_t sampleCount,
                                    double threshold, double minExpected) {
  ChiSquareResult r;
  r.observed = observed;
  r.expected = expected;
  r.threshold = threshold;
  const size_t cells = observed.values.size();
  std::vector<size_t> order(cells);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return expected.values[a] < expected.values[b]; });

  double poolObserved = 0, poolExpected = 0;
  int scored = 0;
  double chi2 = 0;
  for (size_t i : order) {
    const double o = observed.values[i], e = expected.values[i];
    if (!std::isfinite(e) || e < 0) {
      r.failure = "expected count is " + std::to_string(e) + " in cell " + std::to_string(i) +
                  ": the pdf is negative or not finite there";
      return r;
    }
    if (e == 0.0 && o > 0.0) {
      // The pdf integrates to exactly 0 here although the quadrature evaluated it at the
      // centroid of these very samples (integrateCells' probe): the sampler leaves the pdf's
      // support. Pooling would hide them (a pool of zero expectation cannot be scored), so
      // they reject, however few.
      std::ostringstream msg;
      msg << o << " of " << sampleCount << " samples in cell (row " << i / observed.cols << ", col "
          << i % observed.cols << ") where the pdf integrates to 0: the sampler leaves the pdf's support";
      r.failure = msg.str();
      return r;
    }
    if (e < minExpected) {
      poolObserved += o;
      poolExpected += e;
      ++r.pooledCells;
    } else if (poolExpected > 0 && poolExpected < minExpected) {
      // The pool is too small to score alone: merge it into this (the smallest scored) cell.
      poolObserved += o;
      poolExpected += e;
    } else {
      chi2 += sqr(o - e) / e;
      ++scored;
    }
  }
  if (poolExpected > 0) {
    chi2 += sqr(poolObserved - poolExpected) / poolExpected;
    ++scored;
  }
  r.statistic = chi2;
  r.dof = scored - 1;
  if (r.dof < 1) {
    // Every sample fell into one scored cell (a delta lobe, or a lobe narrower than a cell):
    // a chi-square with 0 degrees of freedom has no distribution, so there is no p-value. What
    // is left to test is the count itself, O ~ Binomial(N, E / N) ~ Normal(E, E): it must lie
    // within CountSigmas standard deviations of E.
    r.dof = 0;
    r.pValue = std::numeric_limits<double>::quiet_NaN();
    r.countZ = std::sqrt(chi2);
    r.passed = r.countZ <= CountSigmas;
    if (!r.passed) {
      std::ostringstream msg;
      msg << "no degrees of freedom (one scored cell): the count is " << r.countZ
          << " standard deviations from its expectation, more than " << CountSigmas;
      r.failure = msg.str();
    }
    return r;
  }
  r.pValue = Eigen::numext::igammac(0.5 * r.dof, 0.5 * chi2);
  if (!std::isfinite(r.pValue)) {
    r.failure = "p-value is not finite (chi2 = " + std::to_string(chi2) + ")";
    return r;
  }
  r.passed = r.pValue >= threshold;
  return r;
}

ChiSquareResult chiSquareVerdict(const SampleHistogram& histogram, const std::vector<double>& pdfIntegrals,
                                 const SphericalGrid& grid, size_t sampleCount, double threshold,
                                 double minExpected) {
  ChiSquareResult r =
      chiSquareFromTables(histogram.counts, expectedCounts(grid, pdfIntegrals, histogram.deltas, sampleCount),
                          sampleCount, threshold, minExpected);
  if (histogram.invalidSamples > 0) {
    r.passed = false;
    r.failure =
        std::to_string(histogram.invalidSamples) + " invalid samples, first: " + histogram.firstInvalid;
  } else if (!histogram.deltaMismatch.empty()) {
    r.passed = false;
    r.failure = histogram.deltaMismatch;
  }
  return r;
}

double sidakSignificance(double alpha, int testCount) {
  if (testCount <= 1) return alpha;
  // 1 - (1 - alpha)^(1/m), via log1p/expm1: the naive form loses digits for large m.
  return -std::expm1(std::log1p(-alpha) / testCount);
}

}  // namespace scatterlab
