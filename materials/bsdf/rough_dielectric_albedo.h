// Directional albedo of the rough dielectric's single-scattering lobes, reflection and
// transmission apart: E(wi) = integral of f(wi, wo) |cos wo| over each hemisphere of wo.
// What energy compensation tabulates (Kulla & Conty 2017: E(mu, alpha) and its average) and
// what the tests compare the kit's sphere quadrature with.
//
// Integrated over the visible-normal sample square rather than over wo: with
// m = sampleVisible(wi, u), E_R = integral F(wi.m) w_R(m) du and E_T = integral (1 - F(wi.m))
// w_T(m) du, where w = f |cos wo| / pdf is the sample weight (G2 / G1, at most 1). The
// integrand is bounded and smooth except where wo crosses the horizon, whereas f is as
// narrow as the lobe (alpha = 0.001), so a deterministic adaptive quadrature converges
// without knowing where the lobe is. It is the expectation that sample() estimates by Monte
// Carlo, computed by quadrature.
#pragma once

#include "materials/bsdf/rough_dielectric.h"
#include "materials/core/quadrature.h"

namespace scatterlab {

struct LobeAlbedo {
  double reflection = 0.0;
  double transmission = 0.0;
  double total() const { return reflection + transmission; }
};

inline QuadratureOptions albedoQuadrature() {
  QuadratureOptions q;
  q.relativeTolerance = 1e-6;
  q.absoluteTolerance = 1e-9;
  return q;
}

// Albedo in the given transport mode. Importance is the energy balance (power scattered into
// each hemisphere per unit power arriving from wi); radiance scales the transmitted part by
// 1 / etaRel^2 and is not an energy.
template <typename Distribution>
LobeAlbedo roughDielectricAlbedo(const Distribution& distribution, double eta, const Vec3d& wi, TransportMode mode,
                                 const QuadratureOptions& options = albedoQuadrature()) {
  if (wi.z == 0 || !std::isfinite(wi.z)) return {};
  const auto integrand = [&](double u0, double u1) {
    const Vec3d m = sampleRoughDielectricNormal(distribution, wi, Vec2d(u0, u1));
    const double fresnel = fresnelDielectric(glm::dot(wi, m), eta);
    glm::dvec2 weights(0.0);
    if (fresnel > 0)
      if (const auto s = scatterRoughDielectric(distribution, eta, wi, m, false, mode)) weights.x = fresnel * s->weight.x;
    if (fresnel < 1)
      if (const auto s = scatterRoughDielectric(distribution, eta, wi, m, true, mode))
        weights.y = (1.0 - fresnel) * s->weight.x;
    return weights;
  };
  // u0 = 1 is the rim of the visible normals' disk, normals on the horizon, where the
  // weights drop to 0 at the end point itself: Simpson's rule would refine the last piece to
  // its maximum depth in every inner integral. The integrand is at most 1, so stopping 2^-40
  // short of the rim changes E by less than 1e-12.
  constexpr double BeforeRim = 1.0 - 0x1p-40;
  const glm::dvec2 e = adaptiveSimpson2D(integrand, 0.0, BeforeRim, 0.0, 1.0, options);
  return {e.x, e.y};
}

}  // namespace scatterlab
