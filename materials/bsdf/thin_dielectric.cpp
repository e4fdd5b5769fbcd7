// The material registry's "thin-dielectric" model (thin_dielectric.h): its parameter spec and the function
// that builds it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/thin_dielectric.h"

#include <memory>

#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildThinDielectric(const MaterialParameters& p) {
  return std::make_unique<ThinDielectricBsdf>(p.number("eta"));
}

}  // namespace

MaterialModel thinDielectricModel() {
  return {
      .type = "thin-dielectric",
      .description =
          "Thin sheet (window pane): mirror reflection R' = R + T^2 R / (1 - R^2) of all internal "
          "bounces, the rest straight through, lossless",
      .citation = "pbrt-v4 ThinDielectricBxDF (Pharr, Jakob & Humphreys 2023, section 9.5)",
      .parameters = {dielectricIndexParameter(
          DielectricIndexRange, "index of refraction of the sheet relative to the medium around it")},
      .alternatives = {},
      .build = buildThinDielectric,
      .losslessExamples = {{{"type", "thin-dielectric"}, {"eta", 1.5}}},
  };
}

}  // namespace scatterlab
