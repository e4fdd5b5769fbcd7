// The classical dipole of Jensen, Marschner, Levoy & Hanrahan 2001, "A Practical Model for
// Subsurface Light Transport" (SIGGRAPH), in Donner's corrected form of the profile:
//   A = (1 + Fdr) / (1 - Fdr), sigma_tr = sqrt(3 sigma_a sigma_t'), z_r = 1 / sigma_t',
//   z_v = z_r (1 + 4A/3), d = sqrt(r^2 + z^2),
//   Rd(r) = alpha' / (4 pi) [z_r (1 + sigma_tr d_r) e^(-sigma_tr d_r) / d_r^3
//                            + z_v (1 + sigma_tr d_v) e^(-sigma_tr d_v) / d_v^3]      (eq. 5)
//   Rd = (alpha' / 2) (1 + e^(-(4/3) A sqrt(3 (1 - alpha')))) e^(-sqrt(3 (1 - alpha')))  (eq. 6 integrated)
// Fdr is the diffuse reflectance of the boundary for light inside the medium (relative index
// 1 / eta seen from inside), computed exactly (diffuse_fresnel.h) rather than by Egan &
// Hilgeman's polynomial that Jensen et al. used: the two differ by < 4e-4 for eta in [1.3, 1.5]
// and both reproduce the paper's diffuse reflectances to the digits it prints.
#pragma once

#include "materials/bssrdf/cumulative_profile.h"
#include "materials/bssrdf/diffusion_source.h"

namespace scatterlab {

// A = (1 + Fdr) / (1 - Fdr) of a medium with relative index eta (inside / outside).
double jensenBoundaryFactor(double eta);

template <typename T> struct JensenDipole { T alphaPrime, sigmaTr, zr, zv; };

template <typename T>
JensenDipole<T> makeJensenDipole(const T& sigmaSPrime, const T& sigmaA, double boundaryFactor) {
  const T sigmaTPrime = sigmaA + sigmaSPrime;
  const T zr = T(1) / sigmaTPrime;
  return {sigmaSPrime / sigmaTPrime, safeSqrt(T(3) * sigmaA * sigmaTPrime), zr,
          zr * (T(1) + T(4.0 / 3.0 * boundaryFactor))};
}

// Rd(r), mm^-2.
template <typename T> T jensenDipoleProfile(const JensenDipole<T>& d, const T& r) {
  return d.alphaPrime * T(1 / (4 * Pi)) *
         (pointSourceFlux(d.zr, d.sigmaTr, r) + pointSourceFlux(d.zv, d.sigmaTr, r));
}

// integral_0^r 2 pi r' Rd(r') dr'.
template <typename T> T jensenDipoleCumulative(const JensenDipole<T>& d, const T& r) {
  return d.alphaPrime * T(1 / (4 * Pi)) *
         (pointSourceFluxIntegral(d.zr, d.sigmaTr, r) + pointSourceFluxIntegral(d.zv, d.sigmaTr, r));
}

// The total diffuse reflectance, Jensen et al.'s closed form in alpha' alone.
template <typename T> T jensenDipoleTotal(const T& alphaPrime, double boundaryFactor) {
  using std::exp;
  const T s = safeSqrt(T(3) * (T(1) - alphaPrime));
  return T(0.5) * alphaPrime * (T(1) + exp(T(-4.0 / 3.0 * boundaryFactor) * s)) * exp(-s);
}

class JensenDipoleProfile final : public CumulativeProfile {
 public:
  // Per channel sigma_s' and sigma_a (mm^-1, sigma_s' + sigma_a > 0), and eta.
  JensenDipoleProfile(const Rgb& sigmaSPrime, const Rgb& sigmaA, double eta);

  std::string name() const override { return "dipole"; }
  const JensenDipole<double>& channel(int c) const { return channels_[c]; }

 protected:
  double channelProfile(int c, double r) const override { return jensenDipoleProfile(channels_[c], r); }
  double channelCumulative(int c, double r) const override { return jensenDipoleCumulative(channels_[c], r); }

 private:
  JensenDipole<double> channels_[3];
};

}  // namespace scatterlab
