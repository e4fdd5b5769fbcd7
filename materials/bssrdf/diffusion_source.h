// The two terms of the diffusion solution for an isotropic point source at signed depth z
// below the surface point's normal (z < 0: a virtual source above the surface), observed at
// radius r on the surface, d = sqrt(r^2 + z^2), sigma = sigma_tr, and their integrals over the
// disk of radius r (Farrell, Patterson & Wilson 1992; Jensen et al. 2001 eq. 5; d'Eon 2012):
//   flux     z (1 + sigma d) e^(-sigma d) / d^3     integral 2 pi sign(z) (e^(-sigma|z|) - |z| e^(-sigma d) /
//   d) fluence  e^(-sigma d) / d                        integral 2 pi (e^(-sigma|z|) - e^(-sigma d)) / sigma
// (with 2 pi r dr = 2 pi d dd, both integrate in closed form). The dipoles and photon beam
// diffusion are sums of these; the fluence appears only as a dipole's difference of a real and
// a virtual source, which is written as one term. Everything is written without the
// cancellation of the naive forms (d - |z| = r^2 / (d + |z|), d_v - d_r = (z_v^2 - z_r^2) /
// (d_r + d_v), expm1): the flux integral keeps its relative precision near r = 0, the dipole
// fluence its digits in the far tail, and all stay finite at sigma = 0 (no absorption).
// Templated on T for ceres::Jet; z must not be 0.
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

// (1 - e^(-sigma L)) / sigma, and L in the limit sigma L -> 0.
template <typename T> T oneMinusExpOver(const T& sigma, const T& length) {
  using std::expm1;
  const T x = sigma * length;
  if (x < T(1e-8)) return length * (T(1) - T(0.5) * x);
  return -expm1(-x) / sigma;
}

template <typename T> T pointSourceFlux(const T& z, const T& sigma, const T& r) {
  using std::exp;
  using std::sqrt;
  const T d = sqrt(r * r + z * z);
  return z * (T(1) + sigma * d) * exp(-sigma * d) / (d * d * d);
}

// integral_0^r 2 pi r' pointSourceFlux dr'
//   = 2 pi sign(z) e^(-sigma|z|) [(d - |z|) / d - (|z| / d) expm1(-sigma (d - |z|))].
template <typename T> T pointSourceFluxIntegral(const T& z, const T& sigma, const T& r) {
  using std::abs;
  using std::exp;
  using std::expm1;
  using std::sqrt;
  const T depth = abs(z);
  const T d = sqrt(r * r + z * z);
  const T beyond = r * r / (d + depth);  // d - |z|
  const T value = T(2 * Pi) * exp(-sigma * depth) * (beyond / d - (depth / d) * expm1(-sigma * beyond));
  return z > T(0) ? value : -value;
}

// e^(-sigma d_r) / d_r - e^(-sigma d_v) / d_v, the fluence of a dipole with |zv| > zr > 0, as
// e^(-sigma d_r) [D / (d_r d_v) - expm1(-sigma D) / d_v], D = d_v - d_r = (zv^2 - zr^2) /
// (d_r + d_v): two positive terms, where the plain difference of 1/d-sized numbers loses every
// digit at large r (and makes an adaptive quadrature of the profile refine on noise).
template <typename T> T dipoleFluence(const T& zr, const T& zv, const T& sigma, const T& r) {
  using std::exp;
  using std::expm1;
  using std::sqrt;
  const T dr = sqrt(r * r + zr * zr), dv = sqrt(r * r + zv * zv);
  const T apart = (zv * zv - zr * zr) / (dr + dv);
  return exp(-sigma * dr) * (apart / (dr * dv) - expm1(-sigma * apart) / dv);
}

// integral_0^r 2 pi r' dipoleFluence dr' for a dipole with |zv| > zr > 0: 2 pi [e^(-sigma zr) L(|zv| - zr) -
// e^(-sigma d_r) L(d_v - d_r)], L(x) = oneMinusExpOver(sigma, x), d_v - d_r = (zv^2 - zr^2) / (d_r + d_v).
// The difference of the two single-source integrals would cancel catastrophically at large r when sigma -> 0
// (each grows like r, their difference tends to |zv| - zr); this form has no such cancellation.
template <typename T> T dipoleFluenceIntegral(const T& zr, const T& zv, const T& sigma, const T& r) {
  using std::abs;
  using std::exp;
  using std::sqrt;
  const T depthV = abs(zv);
  const T dr = sqrt(r * r + zr * zr), dv = sqrt(r * r + zv * zv);
  return T(2 * Pi) * (exp(-sigma * zr) * oneMinusExpOver(sigma, depthV - zr) -
                      exp(-sigma * dr) * oneMinusExpOver(sigma, (zv * zv - zr * zr) / (dr + dv)));
}

}  // namespace scatterlab
