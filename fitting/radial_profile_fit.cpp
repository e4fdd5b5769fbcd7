#include "fitting/radial_profile_fit.h"

#include "materials/core/math.h"

namespace scatterlab::fitting::detail {

double radialWeight(RadialWeighting weighting, double r, double value) {
  switch (weighting) {
    case RadialWeighting::Plain: return 1.0;
    case RadialWeighting::Area: return std::sqrt(2.0 * Pi * std::max(r, 0.0));
    case RadialWeighting::Relative: return std::abs(value) > 0 ? 1.0 / std::abs(value) : 0.0;
  }
  return 1.0;
}

}  // namespace scatterlab::fitting::detail
