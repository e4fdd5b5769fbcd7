// Radiance against importance transport, sample by sample (bsdf.h, Veach 1997 section 5.2).
// The same random numbers must give the same direction, pdf, lobe and eta in both modes, and
//   weight(radiance) == weight(importance) / eta^2,
// where eta = BsdfSample::eta must be n(wo) / n(wi) for a transmission lobe (from
// interiorIndex(): 1 above the surface, interiorIndex() below) and 1 for a reflection. Unlike
// the per-mode consistency checks, this also covers delta lobes, whose eval() and pdf() are 0
// and so cannot be compared with their weights.
#pragma once

#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "validation/bsdf_sampling.h"
#include "validation/consistency.h"

namespace scatterlab {

struct TransportModesResult {
  size_t samples = 0;
  size_t violations = 0;
  double maxWeightError = 0.0;  // consistencyError of the weight relation, worst sample
  std::string firstFailure;
  bool passed() const { return violations == 0; }
};

namespace detail {
// What is wrong with one pair of samples drawn with the same numbers, or nothing. `error`
// receives the weight relation's consistencyError when both samples exist.
template <typename Model> const char* transportModesMismatch(const Model& model, const Vec3d& wi,
                                                             const std::optional<BsdfSample>& importance,
                                                             const std::optional<BsdfSample>& radiance,
                                                             double& error) {
  error = 0.0;
  if (importance.has_value() != radiance.has_value()) return "sample() fails in one transport mode only";
  if (!importance) return nullptr;
  const BsdfSample& a = *importance;
  const BsdfSample& b = *radiance;
  if (glm::length(a.wo - b.wo) > 1e-12 || a.lobe != b.lobe || relativeDifference(a.pdf, b.pdf) > 1e-12 ||
      a.eta != b.eta)
    return "direction, pdf, lobe or eta depends on the transport mode";
  const auto index = [&](const Vec3d& w) { return w.z > 0 ? 1.0 : model.interiorIndex(); };
  const double expectedEta = hasAny(a.lobe, LobeFlags::Transmission) ? index(a.wo) / index(wi) : 1.0;
  if (relativeDifference(a.eta, expectedEta) > 1e-12) return "BsdfSample::eta is not n(wo) / n(wi)";
  error = consistencyError(b.weight, a.weight / (a.eta * a.eta));
  if (!(error <= ConsistencyTolerance)) return "radiance weight is not importance weight / eta^2";
  return nullptr;
}
}  // namespace detail

template <typename Model>
TransportModesResult checkTransportModes(const Model& model, const Vec3d& wi, size_t n, uint64_t seed) {
  struct Acc {
    size_t violations = 0;
    double maxError = 0.0;
    size_t firstIndex = SIZE_MAX;
    std::string first;
  };
  const Acc total = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, n, 8192), Acc{},
      [&](const tbb::blocked_range<size_t>& range, Acc acc) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          CounterRng importanceRng(seed, i), radianceRng(seed, i);
          const auto importance = drawBsdfSample(model, wi, importanceRng, TransportMode::Importance);
          const auto radiance = drawBsdfSample(model, wi, radianceRng, TransportMode::Radiance);
          double error = 0.0;
          const char* why = detail::transportModesMismatch(model, wi, importance, radiance, error);
          acc.maxError = std::max(acc.maxError, std::isfinite(error) ? error : INFINITY);
          if (!why) continue;
          ++acc.violations;
          if (i < acc.firstIndex) {
            acc.firstIndex = i;
            acc.first = std::string(why) + " (sample " + std::to_string(i) + ")";
          }
        }
        return acc;
      },
      [](Acc a, const Acc& b) {
        a.violations += b.violations;
        a.maxError = std::max(a.maxError, b.maxError);
        if (b.firstIndex < a.firstIndex) {
          a.firstIndex = b.firstIndex;
          a.first = b.first;
        }
        return a;
      });
  return {n, total.violations, total.maxError, total.first};
}

}  // namespace scatterlab
