// The material registry's "dielectric" model (smooth_dielectric.h): its parameter spec and the function that
// builds it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/smooth_dielectric.h"

#include <memory>

#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildDielectric(const MaterialParameters& p) {
  return std::make_unique<SmoothDielectricBsdf>(p.number("eta"));
}

}  // namespace

MaterialModel dielectricModel() {
  return {
      .type = "dielectric",
      .description =
          "Smooth glass or water: delta reflection and refraction chosen by the exact Fresnel "
          "reflectance (total internal reflection inside), lossless",
      .citation =
          "Fresnel equations with Snell's law (Born & Wolf section 1.5); Veach 1997, section 5.2 "
          "(radiance scaling through refraction); pbrt-v4 DielectricBxDF",
      .parameters = {dielectricIndexParameter(
          DielectricIndexRange, "index of refraction inside (below the surface) relative to outside")},
      .alternatives = {},
      .build = buildDielectric,
      .losslessExamples = {{{"type", "dielectric"}, {"eta", 1.5}}},
  };
}

}  // namespace scatterlab
