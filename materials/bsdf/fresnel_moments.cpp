#include "materials/bsdf/fresnel_moments.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/bsdf/fresnel.h"
#include "materials/core/quadrature.h"

namespace scatterlab {

double fresnelMoment(int k, double eta) {
  if (!(eta > 0.0) || !std::isfinite(eta))
    throw std::invalid_argument("Fresnel moment: eta must be positive and finite, got " +
                                std::to_string(eta));
  if (k < 0) throw std::invalid_argument("Fresnel moment: the order must be >= 0, got " + std::to_string(k));
  // From the denser side (eta < 1), mu below the critical cosine is totally reflected: that
  // part integrates to mu_c^(k+1) / (k+1) exactly, and the quadrature starts at the kink.
  const double criticalCos = eta < 1.0 ? std::sqrt(1.0 - eta * eta) : 0.0;
  QuadratureOptions options;
  options.relativeTolerance = 1e-12;
  options.absoluteTolerance = 1e-15;
  options.minDepth = 4;
  const double transmitting =
      adaptiveSimpson([eta, k](double mu) { return fresnelDielectric(mu, eta) * std::pow(mu, k); },
                      criticalCos, 1.0, options);
  return std::pow(criticalCos, k + 1) / (k + 1) + transmitting;
}

}  // namespace scatterlab
