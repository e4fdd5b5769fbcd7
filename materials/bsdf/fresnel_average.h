// Cosine-weighted hemispherical averages of a reflectance, F_avg = 2 integral_0^1 F(mu) mu dmu:
// the fraction of light arriving uniformly from the hemisphere (radiance, so weighted by the
// cosine) that a smooth interface reflects. Kulla & Conty 2017 colour their multiple-scattering
// term with it (kulla_conty.h). Computed by quadrature, per channel.
#pragma once

#include <algorithm>

#include "materials/bsdf/fresnel.h"
#include "materials/core/quadrature.h"

namespace scatterlab {

// 2 integral_0^1 f(mu) mu dmu for f smooth on [0, 1] (a scalar or a glm vector), to relative
// accuracy ~1e-10.
template <typename F> auto cosineWeightedAverage(const F& f) {
  QuadratureOptions options;
  options.relativeTolerance = 1e-11;
  options.absoluteTolerance = 1e-15;
  options.minDepth = 3;
  return 2.0 * adaptiveSimpson([&](double mu) { return f(mu) * mu; }, 0.0, 1.0, options);
}

// F_avg of the conductor Fresnel term per linear-RGB channel.
inline Rgb conductorFresnelAverage(const Rgb& eta, const Rgb& k) {
  return cosineWeightedAverage([&](double mu) { return fresnelConductor(mu, eta, k); });
}

// A perfect conductor (k -> infinity) reflects everything: F = 1 to round-off. Taken as F_avg
// within PerfectConductorTolerance of 1 in every channel (F <= 1, so no angle reflects much
// less); such a conductor is lossless within that tolerance.
inline constexpr double PerfectConductorTolerance = 1e-9;
inline bool isPerfectConductor(const Rgb& eta, const Rgb& k) {
  const Rgb average = conductorFresnelAverage(eta, k);
  return std::min({average.x, average.y, average.z}) >= 1.0 - PerfectConductorTolerance;
}

}  // namespace scatterlab
