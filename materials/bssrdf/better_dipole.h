// d'Eon 2012, "A Better Dipole" (Technical report, http://www.eugenedeon.com): Grosjean's
// diffusion coefficient and a boundary condition from the Fresnel moments, with both the
// fluence and the flux of the dipole contributing to the exitance:
//   D = (2 sigma_a + sigma_s') / (3 sigma_t'^2), sigma_tr = sqrt(sigma_a / D), z_r = 1 / sigma_t',
//   A = (1 + 3 C2) / (1 - 2 C1), z_v = -z_r - 4 A D, C_phi = (1 - 2 C1) / 4, C_E = (1 - 3 C2) / 2,
//   R(r) = alpha'^2 / (4 pi) [ (C_E z_r (1 + sigma_tr d_r) / d_r^2 + C_phi / D) e^(-sigma_tr d_r) / d_r
//                             - (the same with z_v, d_v) ],
// C1, C2 the Fresnel moments of the boundary seen from inside (fresnel_moments.h, 1 / eta).
// sigma_tr = sqrt(sigma_a / D) is used throughout (docs/references.md, "The better dipole": one open-source
// copy mixes it with Jensen's sqrt(3 sigma_a sigma_t')). Integrating diffusion_source.h's terms gives
//   Rd = alpha'^2 / 2 [C_E (e^(-sigma_tr z_r) + e^(-sigma_tr |z_v|))
//                      + (C_phi / D) e^(-sigma_tr z_r) (1 - e^(-sigma_tr 4 A D)) / sigma_tr],
// which is 1 for alpha' = 1 (C_E + 2 A C_phi = 1): a medium that absorbs nothing reflects all.
#pragma once

#include "materials/bssrdf/cumulative_profile.h"
#include "materials/bssrdf/diffusion_source.h"

namespace scatterlab {

// The boundary constants of a medium with relative index eta: A, C_phi, C_E.
struct FresnelBoundary {
  double A = 1.0, cPhi = 0.25, cE = 0.5;
};
FresnelBoundary fresnelBoundary(double eta);

template <typename T> struct BetterDipole {
  T alphaPrime, sigmaTr, D, zr, zv;
  double cPhi, cE;
};

template <typename T>
BetterDipole<T> makeBetterDipole(const T& sigmaSPrime, const T& sigmaA, const FresnelBoundary& boundary) {
  const T sigmaTPrime = sigmaA + sigmaSPrime;
  const T D = (T(2) * sigmaA + sigmaSPrime) / (T(3) * sigmaTPrime * sigmaTPrime);
  const T zr = T(1) / sigmaTPrime;
  return {sigmaSPrime / sigmaTPrime,   safeSqrt(sigmaA / D), D,          zr,
          -zr - T(4 * boundary.A) * D, boundary.cPhi,        boundary.cE};
}

template <typename T> T betterDipoleProfile(const BetterDipole<T>& d, const T& r) {
  const T flux = pointSourceFlux(d.zr, d.sigmaTr, r) - pointSourceFlux(d.zv, d.sigmaTr, r);
  const T fluence = dipoleFluence(d.zr, d.zv, d.sigmaTr, r);
  return d.alphaPrime * d.alphaPrime * T(1 / (4 * Pi)) * (T(d.cE) * flux + (T(d.cPhi) / d.D) * fluence);
}

template <typename T> T betterDipoleCumulative(const BetterDipole<T>& d, const T& r) {
  const T flux = pointSourceFluxIntegral(d.zr, d.sigmaTr, r) - pointSourceFluxIntegral(d.zv, d.sigmaTr, r);
  const T fluence = dipoleFluenceIntegral(d.zr, d.zv, d.sigmaTr, r);
  return d.alphaPrime * d.alphaPrime * T(1 / (4 * Pi)) * (T(d.cE) * flux + (T(d.cPhi) / d.D) * fluence);
}

template <typename T> T betterDipoleTotal(const BetterDipole<T>& d) {
  using std::abs;
  using std::exp;
  const T real = exp(-d.sigmaTr * d.zr), virtualSource = exp(-d.sigmaTr * abs(d.zv));
  return T(0.5) * d.alphaPrime * d.alphaPrime *
         (T(d.cE) * (real + virtualSource) +
          (T(d.cPhi) / d.D) * real * oneMinusExpOver(d.sigmaTr, abs(d.zv) - d.zr));
}

class BetterDipoleProfile final : public CumulativeProfile {
 public:
  BetterDipoleProfile(const Rgb& sigmaSPrime, const Rgb& sigmaA, double eta);

  std::string name() const override { return "better-dipole"; }
  const BetterDipole<double>& channel(int c) const { return channels_[c]; }

 protected:
  double channelProfile(int c, double r) const override { return betterDipoleProfile(channels_[c], r); }
  double channelCumulative(int c, double r) const override { return betterDipoleCumulative(channels_[c], r); }

 private:
  BetterDipole<double> channels_[3];
};

}  // namespace scatterlab
