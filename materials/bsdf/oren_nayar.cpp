// The material registry's "oren-nayar" model (oren_nayar.h): its parameter spec and the function that builds
// it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/oren_nayar.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildOrenNayar(const MaterialParameters& p) {
  return std::make_unique<OrenNayarBsdf>(p.rgb("albedo"), p.number("sigma"));
}

}  // namespace

MaterialModel orenNayarModel() {
  return {
      .type = "oren-nayar",
      .description = "Rough diffuse (qualitative Oren-Nayar), cosine-weighted sampling",
      .citation =
          "Oren & Nayar 1994, Generalization of Lambert's Reflectance Model, eq. 30 (qualitative model)",
      .parameters = {rgbParameter("albedo", 0.8, "reflectance per linear-RGB channel"),
                     numberParameter("sigma", ValueRange::closed(0.0, PiOver2), 0.35,
                                     "standard deviation of the facet slope angle, in radians")},
      .alternatives = {},
      .build = buildOrenNayar,
      .lobeWidthParameter = "sigma",
  };
}

}  // namespace scatterlab
