// The material registry's "lambertian" model (lambertian.h): its parameter spec and the function that builds
// it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/lambertian.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildLambertian(const MaterialParameters& p) {
  return std::make_unique<LambertianBsdf>(p.rgb("albedo"));
}

}  // namespace

MaterialModel lambertianModel() {
  return {
      .type = "lambertian",
      .description = "Ideal diffuse reflection, f = albedo / pi, cosine-weighted sampling",
      .citation = "J. H. Lambert, Photometria (1760)",
      .parameters = {{.name = "albedo",
                      .kind = ParameterKind::Rgb,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.8,
                      .description = "reflectance per linear-RGB channel"}},
      .alternatives = {},
      .build = buildLambertian,
      .losslessExamples = {{{"type", "lambertian"}, {"albedo", 1.0}}},
  };
}

}  // namespace scatterlab
