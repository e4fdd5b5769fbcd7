// The material registry's "ashikhmin-shirley" and "ngan-ashikhmin-shirley" models (ashikhmin_shirley.h):
// their parameter specs and the functions that build them, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/ashikhmin_shirley.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

// The ngan-* types take the parameter names of Ngan et al. 2005's published fits
// (data/published-fits), so that a fit line means the same thing here.

namespace {

std::unique_ptr<BsdfModel> buildAshikhminShirley(const MaterialParameters& p) {
  const Vec2d n = p.pair("exponent");
  return std::make_unique<AshikhminShirleyBsdf>(
      AshikhminShirleyBsdf::paper(n.x, n.y, p.rgb("rs"), p.rgb("rd")));
}

std::unique_ptr<BsdfModel> buildNganAshikhminShirley(const MaterialParameters& p) {
  return std::make_unique<AshikhminShirleyBsdf>(
      AshikhminShirleyBsdf::ngan(p.rgb("albedo"), p.number("fresnelReflectance"), p.number("sharpness")));
}

}  // namespace

MaterialModel ashikhminShirleyModel() {
  return {
      .type = "ashikhmin-shirley",
      .description =
          "Anisotropic Phong: Schlick-Fresnel half-vector lobe plus the paper's coupled diffuse term",
      .citation =
          "Ashikhmin & Shirley 2000, An Anisotropic Phong BRDF Model, eq. 4 (specular), 5 (diffuse), "
          "9-10 (sampling)",
      .parameters = {{.name = "exponent",
                      .kind = ParameterKind::Pair,
                      .range = ValueRange::closed(0.0, 100000.0),
                      .defaultValue = 100.0,
                      .description =
                          "Phong exponents; [nu, nv] is anisotropic along the tangent and bitangent"},
                     {.name = "rs",
                      .kind = ParameterKind::Rgb,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.05,
                      .description = "specular reflectance at normal incidence (Schlick F0)"},
                     {.name = "rd",
                      .kind = ParameterKind::Rgb,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.5,
                      .description = "diffuse reflectance"}},
      .alternatives = {},
      .build = buildAshikhminShirley,
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false,
  };
}

MaterialModel nganAshikhminShirleyModel() {
  return {
      .type = "ngan-ashikhmin-shirley",
      .description =
          "Isotropic Ashikhmin-Shirley specular lobe (no diffuse term) scaled by an albedo, as Ngan et al.",
      .citation = "Ashikhmin & Shirley 2000, eq. 4; Ngan, Durand & Matusik 2005 (NganAshikhminShirley)",
      .parameters = {rgbParameter("albedo", 0.5, "specular albedo per linear-RGB channel"),
                     {.name = "fresnelReflectance",
                      .kind = ParameterKind::Number,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.5,
                      .description = "Schlick F0"},
                     {.name = "sharpness",
                      .kind = ParameterKind::Number,
                      .range = ValueRange::closed(0.0, 100000.0),
                      .defaultValue = 1000.0,
                      .description = "isotropic Phong exponent n"}},
      .alternatives = {},
      .build = buildNganAshikhminShirley,
      .lobeWidthParameter = "sharpness",
      .widerWhenLarger = false,
  };
}

}  // namespace scatterlab
