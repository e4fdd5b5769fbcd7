#include "materials/bsdf/diffuse_fresnel.h"

#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "materials/bsdf/fresnel.h"
#include "materials/core/quadrature.h"

namespace scatterlab {

namespace {

double integrate(double eta) {
  // From the denser side, mu < sqrt(1 - eta^2) is totally reflected: that part integrates to
  // mu_c^2 exactly, and the quadrature starts at the kink.
  const double criticalCos = eta < 1.0 ? std::sqrt(1.0 - eta * eta) : 0.0;
  QuadratureOptions options;
  options.relativeTolerance = 1e-12;
  options.absoluteTolerance = 1e-15;
  options.minDepth = 4;
  const double transmitting =
      adaptiveSimpson([eta](double mu) { return 2.0 * fresnelDielectric(mu, eta) * mu; }, criticalCos, 1.0, options);
  return criticalCos * criticalCos + transmitting;
}

}  // namespace

double diffuseFresnelReflectance(double eta) {
  if (!(eta > 0.0) || !std::isfinite(eta))
    throw std::invalid_argument("diffuse Fresnel reflectance: eta must be positive and finite, got " +
                                std::to_string(eta));
  static std::mutex mutex;
  static std::map<double, double> cache;
  {
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(eta); it != cache.end()) return it->second;
  }
  const double value = integrate(eta);
  const std::lock_guard lock(mutex);
  // Models take eta from a material's parameters: a handful of values per run.
  if (cache.size() > 1024) cache.clear();
  cache.emplace(eta, value);
  return value;
}

}  // namespace scatterlab
