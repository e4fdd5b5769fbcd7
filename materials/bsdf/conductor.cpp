#include "materials/bsdf/conductor.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scatterlab {

std::unique_ptr<BsdfModel> makeMicrofacetConductor(MicrofacetType type, double alphaX, double alphaY,
                                                   const Rgb& eta, const Rgb& k, MicrofacetSampling sampling,
                                                   MultipleScattering multipleScattering) {
  // D divides by both roughnesses: 0 or a non-finite value has no meaningful lobe.
  for (const double alpha : {alphaX, alphaY}) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("microfacet roughness must be positive and finite, got " +
                                  std::to_string(alpha));
  }
  switch (type) {
    case MicrofacetType::Ggx:
      return std::make_unique<MicrofacetConductorBsdf<GgxDistribution<double>>>(
          GgxDistribution<double>(alphaX, alphaY), eta, k, sampling, multipleScattering);
    case MicrofacetType::Beckmann:
      return std::make_unique<MicrofacetConductorBsdf<BeckmannDistribution<double>>>(
          BeckmannDistribution<double>(alphaX, alphaY), eta, k, sampling, multipleScattering);
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

}  // namespace scatterlab
