// Fresnel moments: FM_k(eta) = integral_0^1 F(mu, eta) mu^k dmu for the exact dielectric
// reflectance F (fresnel.h, eta relative as there: eta_t / eta_i for light arriving from the
// side the normal points to). Diffusion theory's boundary conditions use them for light inside
// a medium of relative index eta going out, FM_k(1 / eta) (d'Eon 2012, "A better dipole",
// C1 and C2; pbrt-v3 bssrdf.cpp fits them with 5th-order polynomials, computed here by
// quadrature). The diffuse Fresnel reflectance is Fdr(eta) = 2 FM_1(eta).
#pragma once

namespace scatterlab {

// Moment k (0, 1 or 2 in use; any k >= 0 works) to ~1e-12 relative. Throws
// std::invalid_argument unless eta is positive and finite.
double fresnelMoment(int k, double eta);

}  // namespace scatterlab
