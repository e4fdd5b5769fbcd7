#include "materials/bsdf/dielectric_index_spec.h"

#include <utility>

namespace scatterlab {

ParameterSpec dielectricIndexParameter(const ValueRange& range, std::string description) {
  return {.name = "eta",
          .kind = ParameterKind::Number,
          .range = range,
          .defaultValue = 1.5,
          .description = std::move(description)};
}

}  // namespace scatterlab
