#include "materials/bsdf/microfacet_spec.h"

namespace scatterlab {

std::vector<ParameterSpec> microfacetParameters() {
  return {{.name = "distribution",
           .kind = ParameterKind::Choice,
           .choices = choiceNames(MicrofacetTypes),
           .defaultValue = "ggx",
           .description = "microfacet normal distribution"},
          {.name = "alpha",
           .kind = ParameterKind::Pair,
           .range = ValueRange::closed(0.001, 1.0),
           .defaultValue = 0.1,
           .description = "roughness; [alpha_x, alpha_y] is anisotropic along the tangent and bitangent"}};
}

ParameterSpec multipleScatteringParameter(const std::string& lobe) {
  return {.name = "multiscatter",
          .kind = ParameterKind::Choice,
          .choices = choiceNames(MultipleScatterings),
          .defaultValue = "none",
          .description =
              "light scattered more than once between microfacets: lost (\"none\"), or returned by "
              "Kulla & Conty 2017's lobe with " +
              lobe + " (\"kulla-conty\")"};
}

}  // namespace scatterlab
