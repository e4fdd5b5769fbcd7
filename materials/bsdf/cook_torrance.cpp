// The material registry's "ngan-cook-torrance" model (cook_torrance.h): its parameter spec and the function
// that builds it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/cook_torrance.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

// The ngan-* types take the parameter names of Ngan et al. 2005's published fits
// (data/published-fits), so that a fit line means the same thing here.

namespace {

std::unique_ptr<BsdfModel> buildNganCookTorrance(const MaterialParameters& p) {
  return std::make_unique<NganCookTorranceBsdf>(p.rgb("albedo"), p.number("eta"), p.number("roughness"));
}

}  // namespace

MaterialModel nganCookTorranceModel() {
  return {
      .type = "ngan-cook-torrance",
      .description =
          "Cook-Torrance as Ngan et al.: Beckmann, V-groove shadowing, Schlick F0, pi normalisation "
          "(reflects up to 4/pi x albedo)",
      .citation =
          "Cook & Torrance 1982, A Reflectance Model for Computer Graphics; Ngan, Durand & Matusik 2005 "
          "(NganCookTorrance)",
      .parameters = {rgbParameter("albedo", 0.5, "specular albedo per linear-RGB channel"),
                     {.name = "eta",
                      .kind = ParameterKind::Number,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.5,
                      .description = "Schlick F0 (Ngan's name for it)"},
                     {.name = "roughness",
                      .kind = ParameterKind::Number,
                      .range = ValueRange::closed(0.001, 1.0),
                      .defaultValue = 0.1,
                      .description = "Beckmann roughness alpha"}},
      .alternatives = {},
      .build = buildNganCookTorrance,
      .lobeWidthParameter = "roughness",
  };
}

}  // namespace scatterlab
