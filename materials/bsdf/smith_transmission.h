// Smith height-correlated masking-shadowing for a refraction pair (Heitz 2014, "Understanding
// the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2), section 6.3).
//
// For reflection (both directions above) the height-correlated form is
// 1 / (1 + Lambda(wi) + Lambda(wo)) (Heitz 2014 eq. 99; SmithMicrofacet::G2). For refraction
// the two directions see the microsurface from opposite sides: a point at height h with
// u = C1(h) (the height CDF, uniform over the visible points) is unmasked from above with
// probability u^Lambda(wi) and unshadowed from below with (1 - u)^Lambda(wo), so
//   G2 = integral_0^1 u^Lambda(wi) (1 - u)^Lambda(wo) du = B(1 + Lambda(wi), 1 + Lambda(wo)),
// Euler's Beta function. A high point is likely visible from above and hidden from below,
// hence G2 <= G1(wi) G1(wo) (Chebyshev's sum inequality), whereas the reflection form,
// which pbrt-v4 also uses for refraction, exceeds the product.
#pragma once

#include "materials/core/special_functions.h"
#include "materials/core/spherical.h"

namespace scatterlab {

// Directions on opposite sides of the surface; symmetric in wi and wo. The Beta function is
// computed through ln Gamma, whose terms grow as Lambda ln Lambda: their cancellation costs
// ~1e-16 Lambda ln Lambda of relative accuracy. Lambda >= 1e8 happens only within ~1e-8 alpha
// of the horizon, where G2 <= 1e-8; it is returned as 0 rather than computed to 1e-6.
template <typename T, typename Distribution>
T smithG2Transmission(const Distribution& distribution, const Vec3<T>& wi, const Vec3<T>& wo) {
  const T lambdaI = distribution.lambda(wi), lambdaO = distribution.lambda(wo);
  constexpr double Negligible = 1e8;
  if (!(lambdaI < T(Negligible)) || !(lambdaO < T(Negligible))) return T(0);
  return betaFunction(T(1) + lambdaI, T(1) + lambdaO);
}

}  // namespace scatterlab
