// Reciprocity (VALIDATION.md section 4), on random direction pairs over the whole sphere:
// BRDF pairs (same side) need f(wi, wo) == f(wo, wi); BTDF pairs (opposite sides) need the
// generalised relation f(wi, wo) / eta_o^2 == f(wo, wi) / eta_i^2 (Veach 1997, eq. 5.14),
// with eta = 1 outside (z > 0) and the model's relative index inside.
#pragma once

#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "validation/consistency.h"

namespace scatterlab {

inline constexpr double ReciprocityTolerance = 1e-6;

struct ReciprocityResult {
  size_t pairs = 0;
  size_t violations = 0;
  double maxError = 0.0;
  std::string worst;  // the worst pair and both values
  bool passed() const { return violations == 0; }
};

ReciprocityResult makeReciprocityResult(size_t pairs, size_t violations, double maxError, const Vec3d& wi,
                                        const Vec3d& wo, const Rgb& forward, const Rgb& backward);

// `interiorEta`: the index of refraction below the surface relative to above (1 for BRDFs).
template <typename Model>
ReciprocityResult checkReciprocity(const Model& model, size_t pairs, uint64_t seed, double interiorEta = 1.0) {
  struct Acc {
    size_t violations = 0;
    double maxError = 0.0;
    size_t worstIndex = SIZE_MAX;
    Vec3d wi{0}, wo{0};
    Rgb forward{0}, backward{0};
  };
  const Acc total = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, pairs, 1024), Acc{},
      [&](const tbb::blocked_range<size_t>& range, Acc acc) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          CounterRng rng(seed, i);
          const Vec3d wi = sampleUniformSphere(rng.uniform2D());
          const Vec3d wo = sampleUniformSphere(rng.uniform2D());
          const double etaI = wi.z > 0 ? 1.0 : interiorEta, etaO = wo.z > 0 ? 1.0 : interiorEta;
          const Rgb forward = model.eval(wi, wo, TransportMode::Radiance) / (etaO * etaO);
          const Rgb backward = model.eval(wo, wi, TransportMode::Radiance) / (etaI * etaI);
          // Relative to the larger value, with no absolute floor: reciprocity is exact.
          double error = 0.0;
          for (int c = 0; c < 3; ++c) error = std::max(error, relativeDifference(forward[c], backward[c]));
          if (!(error <= ReciprocityTolerance)) ++acc.violations;
          if (!(error <= acc.maxError)) {
            acc.maxError = std::isfinite(error) ? error : INFINITY;
            acc = Acc{acc.violations, acc.maxError, i, wi, wo, forward, backward};
          }
        }
        return acc;
      },
      [](Acc a, const Acc& b) {
        const size_t violations = a.violations + b.violations;
        if (b.maxError > a.maxError) a = b;
        a.violations = violations;
        return a;
      });
  return makeReciprocityResult(pairs, total.violations, total.maxError, total.wi, total.wo, total.forward,
                               total.backward);
}

}  // namespace scatterlab
