// Multiple-scattering energy compensation of the rough dielectric (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks", SIGGRAPH course, the dielectric part;
// after Kelemen & Szirmay-Kalos 2001), for isotropic GGX or Beckmann roughness.
//
// The lobe. Light arriving from side s (outside: above the surface, index 1; inside: below,
// index eta) at |cos| mu is scattered once into both hemispheres with the importance albedo
// E_s(mu) = E_R + E_T (rough_dielectric_albedo.h); the rest, 1 - E_s(mu), leaves after more
// bounces among the microfacets. With the averages Ebar_s = 2 integral_0^1 E_s(mu) mu dmu and
// the split r_s (the share of that light that leaves on side s), the lobe in importance
// transport is, for wo on the same side s and on the other side s',
//   f_ms,R(wi, wo) = r_s (1 - E_s(mu_i)) (1 - E_s(mu_o)) / (pi (1 - Ebar_s)),
//   f_ms,T(wi, wo) = (1 - r_s) (1 - E_s(mu_i)) (1 - E_s'(mu_o)) / (pi (1 - Ebar_s')).
// Integrated against |cos wo| over each hemisphere, these return r_s (1 - E_s(mu_i)) and
// (1 - r_s) (1 - E_s(mu_i)): together exactly the light single scattering misses, at every wi
// and for any r_s, so single scattering plus the lobe is lossless (with the table's E; its
// interpolation error is the furnace's error). The reflection part is symmetric in wi and wo.
// In radiance transport the transmission part is divided by etaRel^2 = (n(wo) / n(wi))^2,
// like the single-scattering BTDF (Veach 1997 section 5.2), so that
// f(wi, wo, radiance) = f(wo, wi, importance).
//
// The split. The generalised reciprocity the kit checks, f(wi, wo) / n(wo)^2 = f(wo, wi) /
// n(wi)^2 in importance transport (validation/reciprocity.h), holds for the transmission part
// if and only if
//   (1 - r_out) (1 - Ebar_out) = eta^2 (1 - r_in) (1 - Ebar_in) =: tau,
// the multiply scattered power crossing the interface under uniform illumination (detailed
// balance: the exterior's radiance is the interior's divided by eta^2). It leaves one degree
// of freedom. Kulla & Conty take (1 - r_out) = (1 - F_avg,out) x, (1 - r_in) = (1 - F_avg,in)
// (1 - x) with x fixed by the constraint; a random walk on the Smith microsurface (Heitz,
// Hanika, d'Eon & Dachsbacher 2016, "Multiple-Scattering Microfacet BSDFs with the Smith
// Model"; tests/materials/bsdf/rough_dielectric_multiscatter_test.cpp) shows instead that the
// light multiply scattered from the optically thinner side (outside) almost all crosses:
// 92-99.8% for GGX alpha 0.3 .. 1, eta 1.05 .. 2.4, where Kulla & Conty's split gives 59% at
// alpha 1, eta 1.5 (and 50%, with reflection, for an index-matched interface, which reflects
// nothing). So scatterlab takes the largest crossing flux that reciprocity allows with both
// shares in [0, 1]:
//   tau = min(1 - Ebar_out, eta^2 (1 - Ebar_in)),
//   1 - r_out = tau / (1 - Ebar_out),   1 - r_in = tau / (eta^2 (1 - Ebar_in)).
// In every case measured the first term is the smaller (inside loses more: total internal
// reflection traps light among the facets), so all the outside's multiply scattered light
// crosses (the walk: 92% at alpha 0.3, eta 1.5; 95-99.8% at alpha 1), and the inside's share
// follows from reciprocity: it agrees with the walk's within 0.007 (0.235 against 0.233 at
// alpha 1, eta 1.5; 0.107 against 0.101 at alpha 0.3; 0.737 against 0.736 at alpha 1, eta
// 1.05), where Kulla & Conty's split gives 0.14 at alpha 1, eta 1.5.
//
// The tables. E_s(mu) depends on (alpha, eta, distribution) and on the side. It is tabulated
// per material at construction (DielectricAlbedoTable), by the fixed-rule quadrature of
// roughDielectricAlbedoAboutIncidence (within 5e-5 of the adaptive reference, ~2 ms a value),
// at nodes placed adaptively in s = ln(mu + 1e-6) + mu / 0.1 (log-spaced toward grazing, where
// E changes on the scale mu ~ alpha and below it as a power of mu, and ~0.01 apart near the
// normal): starting from 25 nodes uniform in s, every interval whose midpoint the interpolant
// (PiecewiseCubic1D) misses by more than 1e-4 is split, down to mu = 1e-5, after nodes are
// forced at mu = (1/4 .. 4) alpha and, inside, around the critical cosine (features narrower
// than the first spacing). A table has 55-100 nodes; both sides take 0.1-0.3 s to build
// (cached: materials with the same distribution, roughness and index share them). Against
// the quadrature at random mu the interpolant is within 6.1e-5 (1e-4 asserted) for GGX and
// Beckmann, alpha 0.001 .. 1, eta 1.05 .. 2.4. Below mu = 1e-5 (within 6e-4 degrees of the horizon) E is the
// interpolant toward its value at mu = 1e-9, which may differ from E there by a few percent
// at alpha >= 0.1 (E falls as a power of mu at grazing incidence); the energy there is below
// 1e-10 of a hemisphere's. The averages Ebar_s are integrals of the interpolants, so the
// compensation is normalised exactly for the E it uses. Anisotropic roughness is not
// supported: its tables would need a row per azimuth, 16 times the cost.
//
// Sampling: RoughDielectricCompensation::sample draws the reflection part with probability
// r_s, else the transmission part, each from the side's LossLobeSampler (kulla_conty.h: a
// tabulated density close to (1 - E(mu_o)) mu_o with an exact pdf); rough_dielectric.h mixes
// it with single scattering.
#pragma once

#include <memory>
#include <optional>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/kulla_conty.h"
#include "materials/bsdf/microfacet_type.h"
#include "materials/core/piecewise_cubic.h"

namespace scatterlab {

// E_s(mu) for one side of one material (the header comment).
class DielectricAlbedoTable {
 public:
  // alpha in (0, 1] (isotropic), eta > 0 and != 1 (std::invalid_argument otherwise).
  DielectricAlbedoTable(MicrofacetType type, double alpha, double eta, bool inside);

  // E at |cos| = mu (clamped to [0, 1]), in [0, 1].
  double operator()(double mu) const;
  double loss(double mu) const { return 1.0 - (*this)(mu); }
  // 1 - Ebar = 2 integral_0^1 (1 - E(mu)) mu dmu of the interpolant (relative accuracy 1e-9).
  double averageLoss() const { return averageLoss_; }
  size_t nodeCount() const { return table_.size(); }
  // The node i: mu and E there.
  double nodeCos(size_t i) const { return nodeCos_[i]; }
  double nodeValue(size_t i) const { return table_.value(i); }

  // The table's coordinate s(mu) and its inverse.
  static double coordinate(double mu);
  static double cosAt(double s);

  static constexpr double Tolerance = 1e-4;     // interpolant against quadrature at midpoints
  static constexpr double RefinedAbove = 1e-5;  // intervals are split only above this mu
  static constexpr double GrazingCos = 1e-9;    // where the mu = 0 node is computed
  static constexpr int InitialNodes = 25;
  static constexpr int MaxNodes = 400;

 private:
  PiecewiseCubic1D table_;       // E over s
  std::vector<double> nodeCos_;  // mu at the nodes
  double averageLoss_ = 0.0;
};

// E_s(mu) of one side at one material, by the quadrature the tables use.
double dielectricAlbedo(MicrofacetType type, double alpha, double eta, double mu, bool inside);

// The compensation lobe of one distribution, roughness and index: both sides' tables, the split
// and the samplers. Immutable and shared.
class RoughDielectricCompensation {
 public:
  static std::shared_ptr<const RoughDielectricCompensation> shared(MicrofacetType type, double alpha,
                                                                   double eta);
  RoughDielectricCompensation(MicrofacetType type, double alpha, double eta);

  double eta() const { return eta_; }
  const DielectricAlbedoTable& albedo(bool inside) const { return inside ? inside_ : outside_; }
  // E_s at wi's side and |cos|.
  double albedoAt(const Vec3d& w) const { return albedo(w.z < 0)(std::abs(w.z)); }
  // r_s: the share of side s's multiply scattered light that leaves on side s.
  double reflectionShare(bool inside) const { return inside ? reflectionInside_ : reflectionOutside_; }

  // f_ms(wi, wo) given 1 - E_s(mu_i) (looked up once per sample); 0 if a direction is on the
  // horizon.
  double eval(const Vec3d& wi, const Vec3d& wo, double lossI, TransportMode mode) const;
  // The density of sample() per solid angle of wo.
  double pdf(const Vec3d& wi, const Vec3d& wo) const;
  // wo on wi's side with probability r_s (uLobe < r_s), else on the other side; nothing on the
  // measure-zero rim.
  std::optional<Vec3d> sample(const Vec3d& wi, double uLobe, const Vec2d& u) const;

 private:
  const LossLobeSampler& sampler(bool inside) const { return inside ? insideSampler_ : outsideSampler_; }

  double eta_;
  DielectricAlbedoTable outside_, inside_;
  double reflectionOutside_ = 1.0, reflectionInside_ = 1.0;
  LossLobeSampler outsideSampler_, insideSampler_;
};

}  // namespace scatterlab
