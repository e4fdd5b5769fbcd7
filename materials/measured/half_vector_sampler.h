// Importance sampling of a tabulated isotropic BRDF through its half vector, with an exact pdf.
//
// For each of K incident polar angles theta_k (nodes at the centres of K equal bins of
// [0, pi/2)), a continuous density of h over (x, phi) = (1 - cos theta_h, phi_h - phi_i), in
// which d(omega_h) = dx dphi: the bilinear interpolation (piecewise_bilinear.h) of vertex
// values on a grid whose theta_h edges are the 90 non-linear MERL cell edges (dense next to
// the highlight, so a near-mirror lobe spans many cells) and whose phi edges are P uniform
// cells. A vertex's value is the density with which the BRDF sends energy through h there,
// f(wi, wo) cos(theta_o) d(omega_o) / d(omega_h) = f cos(theta_o) 4 (wi.h) (channel mean); at the
// pole every phi shares one value and phi = pi repeats phi = -pi, so the density is
// continuous in h. wo = reflect(wi, h) then has density p(h) / (4 wo.h) (Walter et al. 2007
// eq. 14). The vertex values only shape the proposal: a poor guess costs variance, never
// bias, because pdf() reads the very tables that sample() inverts. Being continuous, the pdf
// is also cheap for the chi-square kit to integrate.
//
// Between nodes the two neighbouring densities are mixed with the linear weights of theta_i
// (a mixture, so still exact), and a fraction `cosineFraction` of the samples is
// cosine-weighted (defensive sampling, Hesterberg 1995), so that pdf > 0 wherever f can be
// > 0, including where the vertex values vanish below the horizon.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "materials/core/math.h"
#include "materials/core/piecewise_bilinear.h"

namespace scatterlab {

struct HalfVectorSamplerOptions {
  int incidentNodes = 45;       // theta_i nodes over [0, pi/2): every 2 degrees
  int phiCells = 64;            // azimuth cells of phi_h - phi_i over [-pi, pi)
  double cosineFraction = 0.1;  // share of cosine-weighted samples
};

class HalfVectorSampler {
 public:
  using Brdf = std::function<Rgb(const Vec3d& wi, const Vec3d& wo)>;

  // Evaluates `brdf` once per grid vertex and node; brdf must be isotropic (depend on wi, wo only
  // through their relative azimuth).
  HalfVectorSampler(const Brdf& brdf, const HalfVectorSamplerOptions& options = {});

  // Density per solid angle of wo; 0 unless both directions are above the surface.
  double pdf(const Vec3d& wi, const Vec3d& wo) const;
  // A direction above the surface, or nothing (wi below the surface, or h reflected wi below
  // the horizon).
  std::optional<Vec3d> sample(const Vec3d& wi, double uLobe, const Vec2d& u) const;

  const HalfVectorSamplerOptions& options() const { return options_; }

 private:
  struct NodeWeights {
    int first, second;  // node indices (equal when only one applies)
    double secondWeight;
  };
  NodeWeights nodeWeights(double cosThetaI) const;

  HalfVectorSamplerOptions options_;
  std::vector<PiecewiseBilinear2D> nodes_;  // per theta_i node, over (1 - cos theta_h, phi_h - phi_i)
};

}  // namespace scatterlab
