// Per-sample consistency (docs/validation.md section 2). The chi-square test only sees where
// samples land; it is blind to eval() and to the weight. Here every sample must satisfy
//   weight == eval(wi, wo) |cos wo| / pdf(wi, wo)  and  sample.pdf == pdf(wi, wo),
// and eval must vanish wherever pdf does (else the sampler cannot reach light the model
// reflects: a biased estimator). The same pass gives the importance-sampled albedo.
// Everything runs in one transport mode: weight and eval must agree in the mode used.
#pragma once

#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "materials/core/warp.h"
#include "validation/bsdf_sampling.h"

namespace scatterlab {

// Relative error with an absolute floor: |a - b| / max(|a|, |b|, 1e-2), so values below 1e-2
// are compared to 1e-6 absolute when the tolerance is 1e-4 (docs/validation.md section 2).
inline double consistencyError(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return a == b ? 0.0 : INFINITY;
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-2});
}
inline double consistencyError(const Rgb& a, const Rgb& b) {
  return std::max({consistencyError(a.x, b.x), consistencyError(a.y, b.y), consistencyError(a.z, b.z)});
}

inline constexpr double ConsistencyTolerance = 1e-4;
// Uniform directions over the sphere at which eval > 0 with pdf == 0 is looked for.
inline constexpr size_t DefaultSupportProbes = 100000;

struct ConsistencyResult {
  size_t samples = 0;
  size_t inconsistentSamples = 0;
  double maxWeightError = 0.0;
  double maxPdfError = 0.0;
  size_t supportProbes = 0;
  size_t supportViolations = 0;  // directions with eval > 0 but pdf == 0
  std::string firstFailure;
  Table2D maxErrorPerCell;  // the worst error of the samples landing in each cell
  Rgb albedoMean{0.0};      // mean weight (failures count 0): importance-sampled albedo
  Rgb albedoStdError{0.0};
  bool passed() const { return inconsistentSamples == 0 && supportViolations == 0; }
};

namespace detail {
struct ConsistencyAccumulator {
  size_t inconsistent = 0;
  double maxWeightError = 0.0, maxPdfError = 0.0;
  size_t firstFailureIndex = SIZE_MAX;
  std::string firstFailure;
  std::vector<double> cellError;
  Rgb sum{0.0}, sumSquares{0.0};
  size_t supportViolations = 0;
  void join(const ConsistencyAccumulator& other);
};
void describeInconsistency(std::string& out, size_t index, const Vec3d& wo, const char* what, double sampled,
                           double recomputed);
}  // namespace detail

template <typename Model>
ConsistencyResult checkConsistency(const Model& model, const Vec3d& wi, const SphericalGrid& grid, size_t n,
                                   uint64_t seed, size_t supportProbes = DefaultSupportProbes,
                                   TransportMode mode = TransportMode::Radiance) {
  using Acc = detail::ConsistencyAccumulator;
  Acc empty;
  empty.cellError.assign(grid.cellCount(), 0.0);
  // parallel_deterministic_reduce splits the same way for any thread count, so the
  // floating-point sums (albedo) are reproducible.
  const Acc total = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, n, 8192), empty,
      [&](const tbb::blocked_range<size_t>& range, Acc acc) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          CounterRng rng(seed, i);
          const std::optional<BsdfSample> s = drawBsdfSample(model, wi, rng, mode);
          if (!s) continue;
          acc.sum += s->weight;
          acc.sumSquares += s->weight * s->weight;
          if (s->isDelta()) continue;  // eval and pdf are 0 for delta lobes by convention
          const double pdf = model.pdf(wi, s->wo, mode);
          const Rgb expectedWeight =
              pdf > 0 ? model.eval(wi, s->wo, mode) * std::abs(s->wo.z) / pdf : Rgb(INFINITY);
          const double weightError = consistencyError(s->weight, expectedWeight);
          const double pdfError = consistencyError(s->pdf, pdf);
          acc.maxWeightError = std::max(acc.maxWeightError, weightError);
          acc.maxPdfError = std::max(acc.maxPdfError, pdfError);
          const double worst = std::max(weightError, pdfError);
          double& cell = acc.cellError[grid.cellIndex(s->wo)];
          cell = std::max(cell, worst);
          if (worst > ConsistencyTolerance) {
            ++acc.inconsistent;
            if (i < acc.firstFailureIndex) {
              acc.firstFailureIndex = i;
              if (weightError >= pdfError)
                detail::describeInconsistency(
                    acc.firstFailure, i, s->wo, "weight (max channel)",
                    std::max({s->weight.x, s->weight.y, s->weight.z}),
                    std::max({expectedWeight.x, expectedWeight.y, expectedWeight.z}));
              else
                detail::describeInconsistency(acc.firstFailure, i, s->wo, "pdf", s->pdf, pdf);
            }
          }
        }
        return acc;
      },
      [](Acc a, const Acc& b) {
        a.join(b);
        return a;
      });

  // Support: uniform directions over the sphere, from a stream disjoint from the samples'.
  // eval counts from the smallest normal double up: in a lobe's far tail eval and pdf are
  // different products of the same vanishing factors, and the pdf may underflow to 0 one
  // step before eval reaches 0 (a Beckmann tail at 5e-324): no light is missed there.
  constexpr double Reflects = std::numeric_limits<double>::min();
  const size_t violations = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, supportProbes, 8192), size_t(0),
      [&](const tbb::blocked_range<size_t>& range, size_t count) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          CounterRng rng(~seed, i);
          const Vec3d wo = sampleUniformSphere(rng.uniform2D());
          const Rgb f = model.eval(wi, wo, mode);
          if ((f.x >= Reflects || f.y >= Reflects || f.z >= Reflects) && !(model.pdf(wi, wo, mode) > 0))
            ++count;
        }
        return count;
      },
      [](size_t a, size_t b) { return a + b; });

  ConsistencyResult r;
  r.samples = n;
  r.inconsistentSamples = total.inconsistent;
  r.maxWeightError = total.maxWeightError;
  r.maxPdfError = total.maxPdfError;
  r.firstFailure = total.firstFailure;
  r.supportProbes = supportProbes;
  r.supportViolations = violations;
  r.maxErrorPerCell = Table2D(grid.thetaBins, grid.phiBins);
  r.maxErrorPerCell.values = total.cellError;
  r.albedoMean = total.sum / double(n);
  const Rgb variance = glm::max(total.sumSquares / double(n) - r.albedoMean * r.albedoMean, Rgb(0.0));
  r.albedoStdError = glm::sqrt(variance / double(n));
  return r;
}

}  // namespace scatterlab
