// Diffuse Fresnel reflectance: the fraction of uniformly diffuse (Lambertian) light that a
// smooth dielectric interface reflects,
//   Fdr(eta) = (1/pi) integral over the hemisphere of F(cos theta, eta) cos theta dw
//            = 2 integral_0^1 F(mu, eta) mu dmu
// (Egan & Hilgeman 1973; Jensen et al. 2001 use their polynomial fit). eta is relative as in
// fresnelDielectric: eta > 1 for light arriving from the rarer side, eta < 1 from the denser
// side, where total internal reflection makes every mu below sqrt(1 - eta^2) reflect fully.
// Computed by adaptive quadrature of fresnelDielectric (no fit), cached per eta.
//
// Energy balance across the interface (etendue n^2 dA cos dw is conserved, so the diffuse
// transmittances from the two sides are related): 1 - Fdr(eta) = eta^2 (1 - Fdr(1 / eta)).
#pragma once

namespace scatterlab {

// Throws std::invalid_argument unless eta is positive and finite.
double diffuseFresnelReflectance(double eta);

}  // namespace scatterlab
