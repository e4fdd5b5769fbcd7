#include "materials/bsdf/rough_dielectric.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scatterlab {

std::unique_ptr<BsdfModel> makeRoughDielectric(MicrofacetType type, double alphaX, double alphaY, double eta,
                                               MultipleScattering multipleScattering) {
  // D divides by both roughnesses: 0 or a non-finite value has no meaningful lobe.
  for (const double alpha : {alphaX, alphaY}) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("microfacet roughness must be positive and finite, got " +
                                  std::to_string(alpha));
  }
  if (!(eta > 0.0) || !std::isfinite(eta) || eta == 1.0)
    throw std::invalid_argument("rough dielectric index must be positive, finite and not 1, got " +
                                std::to_string(eta));
  switch (type) {
    case MicrofacetType::Ggx:
      return std::make_unique<RoughDielectricBsdf<GgxDistribution<double>>>(
          GgxDistribution<double>(alphaX, alphaY), eta, multipleScattering);
    case MicrofacetType::Beckmann:
      return std::make_unique<RoughDielectricBsdf<BeckmannDistribution<double>>>(
          BeckmannDistribution<double>(alphaX, alphaY), eta, multipleScattering);
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

}  // namespace scatterlab
