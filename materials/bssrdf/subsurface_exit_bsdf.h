// The directional term of the separable BSSRDF at the point where light leaves the medium
// (separable_bssrdf.h), as a BSDF the path tracer can do next-event estimation and direction
// sampling with (pbrt-v3's SeparableBSSRDF::Sw as its "BSSRDFAdapter"):
//   f(wi, wo) = Sw(wo) = (1 - F(cos theta_o, eta)) / (pi c),   c = 1 - 2 FM_1(eta),
// for wo above the surface; wi (the side the light came from, inside the medium) plays no part
// and is given as the normal. Its integral against |cos wo| is 1 (the normalisation c), so the
// exit vertex passes on exactly the power the profile brought there. Sampled cosine-weighted:
// weight Sw pi = (1 - F) / c, pdf cos / pi.
#pragma once

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/cosine_lobe.h"
#include "materials/bssrdf/separable_bssrdf.h"

namespace scatterlab {

class SubsurfaceExitBsdf final : public CosineSampledReflection<SubsurfaceExitBsdf> {
 public:
  explicit SubsurfaceExitBsdf(double eta) : eta_(eta), normalization_(separableNormalization(eta)) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (wi.z <= 0 || wo.z <= 0) return Rgb(0.0);
    return Rgb(separableDirectional(wo.z, eta_, normalization_));
  }
  bool isLossless() const override { return true; }
  bool isReciprocal() const override { return false; }  // f depends on wo alone

 private:
  double eta_, normalization_;
};

}  // namespace scatterlab
