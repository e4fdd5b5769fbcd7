// Chandrasekhar's H-function for isotropic scattering with single-scattering albedo c
// (Chandrasekhar 1960, "Radiative Transfer", chapter V, eq. 24):
//   H(mu) = 1 + (c/2) mu H(mu) integral_0^1 H(mu') / (mu + mu') dmu',
// solved by fixed-point iteration of H(mu_i) = 1 / (1 - (c/2) mu_i sum_j w_j H(mu_j) / (mu_i +
// mu_j)) on 64 Gauss-Legendre nodes of [0, 1] (converging monotonically from H = 1 for c < 1),
// then extended to any mu by the same equation (Nystrom interpolation). It gives the exact
// reflectance of the index-matched, isotropically scattering half-space (docs/validation.md
// section 6), the ground truth the random walk must reproduce:
//   BRDF f = (c / 4 pi) H(mu_i) H(mu_o) / (mu_i + mu_o),
//   directional albedo R(mu_0) = 1 - H(mu_0) sqrt(1 - c),
//   white-sky albedo 1 - 2 sqrt(1 - c) integral_0^1 H(mu) mu dmu.
#pragma once

#include <array>

namespace scatterlab {

class ChandrasekharH {
 public:
  static constexpr int NodeCount = 64;

  // c in [0, 1]; iterates until successive iterates differ by < 1e-15 (as c -> 1 the
  // convergence slows: ~150 iterations at c = 0.99, ~1e4 at 1 - 1e-6).
  explicit ChandrasekharH(double albedo);

  double albedo() const { return albedo_; }
  int iterations() const { return iterations_; }
  const std::array<double, NodeCount>& nodes() const;                      // on [0, 1]
  const std::array<double, NodeCount>& weights() const;                    // sum to 1
  const std::array<double, NodeCount>& values() const { return values_; }  // H at the nodes

  double operator()(double mu) const;
  // integral_0^1 H(mu) mu^k dmu by the node rule (k = 0: equals (2/c)(1 - sqrt(1 - c)) once
  // converged, Chandrasekhar's first moment relation).
  double moment(int k) const;

  double directionalAlbedo(double mu0) const;
  double whiteSkyAlbedo() const;
  double brdf(double muI, double muO) const;

 private:
  double albedo_;
  int iterations_ = 0;
  std::array<double, NodeCount> values_{};
};

// The single-scattering albedo c whose index-matched isotropic half-space reflects
// `reflectance` of a normally incident beam, 1 - H(1) sqrt(1 - c) = reflectance (in [0, 1)),
// by bisection in c to 1e-12: what maps Burley's multiple-scattering albedo A of the
// searchlight fits (mfp = 1, g = 0) to the medium a random walk simulates.
double searchlightAlbedoForReflectance(double reflectance);

}  // namespace scatterlab
