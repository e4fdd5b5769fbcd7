#include "validation/reciprocity.h"

#include <sstream>

namespace scatterlab {

ReciprocityResult makeReciprocityResult(size_t pairs, size_t violations, double maxError, const Vec3d& wi,
                                        const Vec3d& wo, const Rgb& forward, const Rgb& backward) {
  ReciprocityResult r;
  r.pairs = pairs;
  r.violations = violations;
  r.maxError = maxError;
  if (maxError > 0) {
    std::ostringstream msg;
    msg.precision(9);
    msg << "worst pair wi=(" << wi.x << ", " << wi.y << ", " << wi.z << ") wo=(" << wo.x << ", " << wo.y
        << ", " << wo.z << "): f(wi,wo)=(" << forward.x << ", " << forward.y << ", " << forward.z
        << ") f(wo,wi)=(" << backward.x << ", " << backward.y << ", " << backward.z << ")";
    r.worst = msg.str();
  }
  return r;
}

}  // namespace scatterlab
