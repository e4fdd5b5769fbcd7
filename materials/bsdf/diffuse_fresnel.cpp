#include "materials/bsdf/diffuse_fresnel.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "materials/bsdf/fresnel_moments.h"

namespace scatterlab {

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
  const double value = 2.0 * fresnelMoment(1, eta);
  const std::lock_guard lock(mutex);
  // Models take eta from a material's parameters: a handful of values per run.
  if (cache.size() > 1024) cache.clear();
  cache.emplace(eta, value);
  return value;
}

}  // namespace scatterlab
