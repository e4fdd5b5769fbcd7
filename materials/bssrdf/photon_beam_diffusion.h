// Photon beam diffusion (Habel, Christensen & Jarosz 2013, "Photon Beam Diffusion: A Hybrid
// Monte Carlo Method for Subsurface Scattering", EGSR), in the form pbrt-v3 tabulates
// (src/core/bssrdf.cpp, BeamDiffusionMS / BeamDiffusionSS): the profile of a beam entering a
// half-space at normal incidence, in optical units (sigma_t = sigma_s + sigma_a = 1, radius r
// in mean free paths), for single-scattering albedo rho and HG parameter g:
//  - multiple scattering: the better dipole (better_dipole.h) of a real source at every depth
//    z of the beam, weighted by the reduced first-scattering density sigma_t' e^(-sigma_t' z)
//    and kappa = 1 - e^(-2 sigma_t' (d_r + z)),
//      MS(r) = integral_0^inf sigma_t' e^(-sigma_t' z) kappa(z) R_bd(r; z_r = z) dz;
//  - single scattering: the beam scatters once at depth t and leaves through the boundary,
//      SS(r) = integral_tc^inf rho e^(-t) e^(-d) p_HG(-t/d) (1 - F(t/d)) (t/d) / d^2 dt,
//    d = sqrt(r^2 + t^2), F the Fresnel reflectance from inside, tc = r sqrt(eta^2 - 1) the
//    depth above which the exit direction is totally reflected.
// pbrt evaluates both integrals with 100 midpoints in the exponential variable, which is
// coarse where the integrands peak at depths ~ r (small radii); here they are integrated by
// Gauss-Legendre panels uniform in ln(depth), accurate to ~1e-7 relative at every radius.
//
// SS diverges like 1/r at r = 0 (the exit point above the beam sees it at every depth); the
// table needs r SS(r) there, beamDiffusionSingleLimit, the integral over the exit angle.
// Kernels are templated on T for rho and g (eta enters as a constant of the boundary).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "materials/bsdf/fresnel.h"
#include "materials/bssrdf/better_dipole.h"
#include "materials/bssrdf/henyey_greenstein.h"
#include "materials/core/gauss_legendre.h"

namespace scatterlab {

namespace detail {

// The value part of a scalar: the number itself, or a ceres::Jet's value. Only quadrature
// grids use it (where to put nodes may depend on a parameter; the integrand's derivative
// still flows through every node).
template <typename T> double valueOf(const T& x) {
  if constexpr (std::is_floating_point_v<T>)
    return x;
  else
    return x.a;
}

// integral_lo^hi f(z) dz (lo > 0) by 8-point Gauss-Legendre on panels of width <= 1.5 in ln z:
// exact for integrands that are polynomials of degree 15 in ln z on each panel, and the depth
// integrands are smooth in ln z wherever they change scale (z ~ r, z ~ 1 / sigma_t).
template <typename T, typename F> T integrateOverLogDepth(const F& f, double lo, double hi) {
  const GaussLegendreRule<8>& rule = gaussLegendre<8>();
  const double a = std::log(lo), b = std::log(hi);
  const int panels = std::max(1, int(std::ceil((b - a) / 1.5)));
  const double width = (b - a) / panels;
  T sum(0);
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < 8; ++i) {
      const double z = std::exp(a + (p + rule.nodes[i]) * width);
      sum += T(rule.weights[i] * width * z) * f(z);
    }
  return sum;
}

// Depths beyond this many (reduced) mean free paths carry e^-45 < 3e-20 of the beam.
inline constexpr double BeamDepthLimit = 45.0;
// Depths below this fraction of min(r, 1 / sigma_t') are left out: the integrands vanish
// linearly there, so what is lost is ~1e-12 relative.
inline constexpr double BeamDepthFloor = 1e-6;

}  // namespace detail

// Multiple scattering MS(r), r > 0, per unit optical area.
template <typename T>
T beamDiffusionMultiple(const T& rho, const T& g, const FresnelBoundary& boundary, double r) {
  using std::exp;
  const T sigmaSPrime = rho * (T(1) - g), sigmaA = T(1) - rho;
  const T sigmaTPrime = sigmaA + sigmaSPrime;
  BetterDipole<T> source = makeBetterDipole(sigmaSPrime, sigmaA, boundary);
  const T virtualOffset = T(4 * boundary.A) * source.D;  // z_v = -z_r - 4 A D
  const double meanFreePath = 1.0 / detail::valueOf(sigmaTPrime);
  const T radius(r);
  return detail::integrateOverLogDepth<T>(
      [&](double z) {
        source.zr = T(z);
        source.zv = -T(z) - virtualOffset;
        const T dr = T(std::sqrt(r * r + z * z));
        const T kappa = T(1) - exp(T(-2) * sigmaTPrime * (dr + T(z)));
        return sigmaTPrime * exp(-sigmaTPrime * T(z)) * kappa * betterDipoleProfile(source, radius);
      },
      detail::BeamDepthFloor * std::min(r, meanFreePath), detail::BeamDepthLimit * meanFreePath);
}

// The single-scattering integrand's angular part at exit cosine mu (inside the medium):
// p_HG(-mu) (1 - F(mu)) mu, with F the reflectance of light leaving the medium.
template <typename T> T beamDiffusionExitFactor(double mu, const T& g, double eta) {
  return henyeyGreenstein(T(-mu), g) * T((1.0 - fresnelDielectric(mu, 1.0 / eta)) * mu);
}

// Single scattering SS(r), r > 0, per unit optical area.
template <typename T> T beamDiffusionSingle(const T& rho, const T& g, double eta, double r) {
  using std::exp;
  const double tc = eta > 1.0 ? r * std::sqrt(eta * eta - 1.0) : 0.0;
  return rho * detail::integrateOverLogDepth<T>(
                   [&](double z) {
                     const double t = tc + z, d = std::sqrt(r * r + t * t);
                     return T(std::exp(-(t + d)) / (d * d)) * beamDiffusionExitFactor(t / d, g, eta);
                   },
                   detail::BeamDepthFloor * r, detail::BeamDepthLimit);
}

// lim_{r -> 0} r SS(r) = rho integral_0^theta_c p_HG(-cos) (1 - F(cos)) cos dtheta (t = r cot
// theta), theta_c the critical angle inside (pi/2 for eta <= 1); 32-point Gauss-Legendre in
// theta_c (1 - v^2) over v, which straightens the square-root edge the transmittance has at
// the critical angle for eta > 1.
template <typename T> T beamDiffusionSingleLimit(const T& rho, const T& g, double eta) {
  const double thetaC = eta > 1.0 ? std::asin(1.0 / eta) : PiOver2;
  const GaussLegendreRule<32>& rule = gaussLegendre<32>();
  T sum(0);
  for (int i = 0; i < 32; ++i) {
    const double v = rule.nodes[i], theta = thetaC * (1.0 - v * v);
    sum += T(rule.weights[i] * 2.0 * thetaC * v) * beamDiffusionExitFactor(std::cos(theta), g, eta);
  }
  return rho * sum;
}

}  // namespace scatterlab
