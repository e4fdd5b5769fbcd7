// Reciprocity (docs/validation.md section 4), on random direction pairs over the whole sphere:
// BRDF pairs (same side) need f(wi, wo) == f(wo, wi); BTDF pairs (opposite sides) need the
// generalised relation (Veach 1997, eq. 5.14), with eta = 1 outside (z > 0) and the model's
// relative index inside.
//
// Veach writes f(w_light -> w_out) / eta_out^2 = f(w_out -> w_light) / eta_light^2 for the
// radiance BSDF with light arriving from the first argument. In scatterlab's convention
// (bsdf.h) light arrives from wo in radiance mode and from wi in importance mode (the adjoint
// BSDF, f*(wi, wo) = f(wo, wi)), so the relation reads, with eta_i = n(wi), eta_o = n(wo):
//   radiance:   f(wi, wo) / eta_i^2 == f(wo, wi) / eta_o^2
//   importance: f(wi, wo) / eta_o^2 == f(wo, wi) / eta_i^2
//   adjoint:    f(wi, wo, radiance) == f(wo, wi, importance)
// For a BRDF, or eta = 1, all three are f(wi, wo) == f(wo, wi).
#pragma once

#include <algorithm>
#include <limits>
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

enum class ReciprocityRelation { Radiance, Importance, Adjoint };

// Relative to the larger value, with no tolerance beyond round-off: reciprocity is exact.
// The one floor is the smallest normal double: below it a value carries fewer significant
// bits (a Beckmann tail at 1e-320 has about ten), so a pair computed in two different orders
// differs there by a whole unit of 4.9e-324; such differences are measured against 2.2e-308.
inline double reciprocityError(double a, double b) {
  const double scale = std::max({std::abs(a), std::abs(b), std::numeric_limits<double>::min()});
  return std::isfinite(a) && std::isfinite(b) ? std::abs(a - b) / scale : (a == b ? 0.0 : INFINITY);
}

// `interiorEta`: the index of refraction below the surface relative to above (1 for BRDFs).
template <typename Model>
ReciprocityResult checkReciprocity(const Model& model, size_t pairs, uint64_t seed, double interiorEta = 1.0,
                                   ReciprocityRelation relation = ReciprocityRelation::Radiance) {
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
          Rgb forward(0.0), backward(0.0);
          switch (relation) {
            case ReciprocityRelation::Radiance:
              forward = model.eval(wi, wo, TransportMode::Radiance) / (etaI * etaI);
              backward = model.eval(wo, wi, TransportMode::Radiance) / (etaO * etaO);
              break;
            case ReciprocityRelation::Importance:
              forward = model.eval(wi, wo, TransportMode::Importance) / (etaO * etaO);
              backward = model.eval(wo, wi, TransportMode::Importance) / (etaI * etaI);
              break;
            case ReciprocityRelation::Adjoint:
              forward = model.eval(wi, wo, TransportMode::Radiance);
              backward = model.eval(wo, wi, TransportMode::Importance);
              break;
          }
          double error = 0.0;
          for (int c = 0; c < 3; ++c) error = std::max(error, reciprocityError(forward[c], backward[c]));
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
