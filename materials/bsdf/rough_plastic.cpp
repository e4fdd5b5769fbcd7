#include "materials/bsdf/rough_plastic.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scatterlab {

std::unique_ptr<BsdfModel> makeRoughPlastic(MicrofacetType type, double alpha, const Rgb& kd, double eta) {
  // D divides by the roughness: 0 or a non-finite value has no meaningful lobe.
  if (!(alpha > 0.0) || !std::isfinite(alpha))
    throw std::invalid_argument("rough plastic: roughness must be positive and finite, got " +
                                std::to_string(alpha));
  if (!(eta >= 1.0) || !std::isfinite(eta))
    throw std::invalid_argument("rough plastic: the coating's index must be finite and >= 1, got " +
                                std::to_string(eta));
  for (int c = 0; c < 3; ++c)
    if (!(kd[c] >= 0.0 && kd[c] <= 1.0))
      throw std::invalid_argument("rough plastic: diffuse reflectance must be in [0, 1], got " +
                                  std::to_string(kd[c]));
  switch (type) {
    case MicrofacetType::Ggx:
      return std::make_unique<RoughPlasticBsdf<GgxDistribution<double>>>(
          GgxDistribution<double>(alpha, alpha), kd, eta);
    case MicrofacetType::Beckmann:
      return std::make_unique<RoughPlasticBsdf<BeckmannDistribution<double>>>(
          BeckmannDistribution<double>(alpha, alpha), kd, eta);
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

}  // namespace scatterlab
