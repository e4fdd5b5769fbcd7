// The BRDF a subsurface material amounts to when the light falls evenly on a large flat piece
// of it: the separable BSSRDF (separable_bssrdf.h) integrated over the entry point,
//   f(wi, wo) = integral over the plane of S(xi, wi; xo, wo) dA(xi)
//             = Ft(wi) Rd Ft(wo) / (pi c),   Ft = 1 - F(cos theta, eta),  c = 1 - 2 FM_1(eta),
// since R integrates to the total diffuse reflectance Rd (bssrdf.h). It is what `scatterlab
// eval` and the explorer show for a subsurface material (docs/explorer.md, "The far-field BRDF
// of a subsurface material"): the directional behaviour of the BSSRDF without its spatial
// spread. Its directional albedo is Ft(wi) Rd (the integral of Ft(wo) |cos wo| / (pi c) is 1 by
// the choice of c), and it is reciprocal. Sampled cosine-weighted, as the renderer samples the
// exit direction of the BSSRDF (subsurface_exit_bsdf.h): weight f pi.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/cosine_lobe.h"
#include "materials/bssrdf/separable_bssrdf.h"

namespace scatterlab {

class SubsurfaceFarFieldBrdf final : public CosineSampledReflection<SubsurfaceFarFieldBrdf> {
 public:
  explicit SubsurfaceFarFieldBrdf(const SeparableBssrdf& bssrdf)
      : eta_(bssrdf.eta()),
        normalization_(bssrdf.normalization()),
        totalReflectance_(bssrdf.profile().totalReflectance()) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0 || wo.z <= 0) return Rgb(0.0);
    // pi c Sw(wi) Sw(wo) = Ft(wi) Ft(wo) / (pi c).
    const double directional = Pi * normalization_ * separableDirectional(wi.z, eta_, normalization_) *
                               separableDirectional(wo.z, eta_, normalization_);
    return directional * totalReflectance_;
  }
  const Rgb& totalReflectance() const { return totalReflectance_; }
  double eta() const { return eta_; }

 private:
  double eta_, normalization_;
  Rgb totalReflectance_;
};

}  // namespace scatterlab
