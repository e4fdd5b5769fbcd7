// The separable BSSRDF (Jensen et al. 2001 eq. 4 with a normalised directional term, as
// pbrt-v3's SeparableBSSRDF):
//   S(xi, wi; xo, wo) = Ft(wi) R(|xi - xo|) Ft(wo) / (pi c),   Ft = 1 - F(cos theta, eta),
// F the exact dielectric Fresnel reflectance at the outside angle (fresnel.h), and
//   c = 1 - 2 FM_1(eta)   (FM_1 the first Fresnel moment from outside, fresnel_moments.h),
// chosen so that the directional term Sw(w) = Ft(w) / (pi c) integrates to 1 against
// |cos| dw over the hemisphere: 2 pi integral_0^1 (1 - F(mu)) mu dmu / (pi c) = (1 - 2 FM_1) / c.
// So light that entered at xi leaves with total power Ft(wi) Rd: what the profile's total
// diffuse reflectance says (bssrdf.h), and nothing more.
#pragma once

#include <memory>

#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/fresnel_moments.h"
#include "materials/bssrdf/bssrdf.h"

namespace scatterlab {

inline double separableNormalization(double eta) { return 1.0 - 2.0 * fresnelMoment(1, eta); }

// Sw(cos theta) = (1 - F(cos theta, eta)) / (pi c), for directions outside (cos theta > 0).
template <typename T> T separableDirectional(const T& cosTheta, double eta, double normalization) {
  return (T(1) - fresnelDielectric(cosTheta, T(eta))) / T(Pi * normalization);
}

class SeparableBssrdf {
 public:
  SeparableBssrdf(std::shared_ptr<const RadialProfile> profile, double eta)
      : profile_(std::move(profile)), eta_(eta), normalization_(separableNormalization(eta)) {}

  // S for entry and exit points `distance` apart, with the cosines of wi and wo to the local
  // normals (outside: > 0; 0 is returned for directions below the surface).
  Rgb eval(double distance, double cosThetaI, double cosThetaO) const {
    if (!(cosThetaI > 0) || !(cosThetaO > 0)) return Rgb(0.0);
    return (Pi * normalization_) * directional(cosThetaI) * directional(cosThetaO) * profile_->eval(distance);
  }
  double directional(double cosTheta) const {
    return cosTheta > 0 ? separableDirectional(cosTheta, eta_, normalization_) : 0.0;
  }
  double normalization() const { return normalization_; }
  double eta() const { return eta_; }
  const RadialProfile& profile() const { return *profile_; }

 private:
  std::shared_ptr<const RadialProfile> profile_;
  double eta_, normalization_;
};

}  // namespace scatterlab
