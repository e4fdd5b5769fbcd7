// Photon beam diffusion tabulated as pbrt-v3 does (ComputeBeamDiffusionBSSRDF): over 100
// single-scattering albedos rho_i = (1 - e^(-8 i / 99)) / (1 - e^-8) (dense toward 1, where
// profiles change fastest) and 64 optical radii r_0 = 0, r_1 = 2.5e-3, r_j = 1.2 r_(j-1)
// (r_63 ~ 203 mean free paths), for one (g, eta). Each row holds, at every radius, the
// cumulative reflectance P(r) = integral_0^r 2 pi r' (MS + SS)(r') dr' and its density
// 2 pi r (MS + SS)(r) (photon_beam_diffusion.h): the radius CDF itself, so a profile is a
// monotone cubic CDF (monotone_cubic_cdf.h) that is evaluated, integrated and inverted
// exactly. P(r_63) is the row's effective albedo rho_eff: the total diffuse reflectance
// (light beyond 203 mean free paths, < 1% only for rho -> 1, is not part of the model).
// Between rows, Catmull-Rom weights on the rho nodes (as pbrt) combine whole rows.
//
// A table costs ~0.3 s of CPU (one thread: materials does no threading); tables are cached per (g, eta).
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "materials/core/monotone_cubic_cdf.h"

namespace scatterlab {

class BeamDiffusionTable {
 public:
  static constexpr int AlbedoCount = 100;
  static constexpr int RadiusCount = 64;

  // Throws std::invalid_argument unless g is in (-1, 1) and eta positive and finite.
  BeamDiffusionTable(double g, double eta);
  // The table for (g, eta), built on first use and shared.
  static std::shared_ptr<const BeamDiffusionTable> shared(double g, double eta);

  double g() const { return g_; }
  double eta() const { return eta_; }
  std::span<const double> albedos() const { return albedos_; }
  std::span<const double> radii() const { return radii_; }  // optical (mean free paths)
  // Row i at radius node j: P(r_j), and the density 2 pi r_j (MS + SS)(r_j).
  double cumulative(int i, int j) const { return cumulative_[i][j]; }
  double density(int i, int j) const { return density_[i][j]; }
  double effectiveAlbedo(int i) const { return cumulative_[i][RadiusCount - 1]; }

  // The radius CDF (unnormalised, optical radius) at any albedo in [0, 1]: Catmull-Rom in rho
  // over the rows, node by node; where the weighted rows would make P decrease (far tails,
  // where neighbouring rows differ by orders of magnitude) the increment is clamped to 0.
  MonotoneCubicCdf profileAt(double rho) const;
  // rho_eff(rho) = profileAt(rho).total(), increasing in rho.
  double effectiveAlbedo(double rho) const { return profileAt(rho).total(); }
  // The albedo whose effective albedo is rhoEff, by bisection to 1e-12 (pbrt's "subsurface
  // from diffuse"); rhoEff above rho_eff(1) gives 1, below 0 gives 0.
  double albedoForEffectiveAlbedo(double rhoEff) const;

 private:
  double g_, eta_;
  std::array<double, AlbedoCount> albedos_{};
  std::array<double, RadiusCount> radii_{};
  std::vector<std::array<double, RadiusCount>> cumulative_, density_;
};

}  // namespace scatterlab
