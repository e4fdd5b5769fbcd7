// The material registry's "phong" and "blinn-phong" models (phong.h): their parameter specs and the functions
// that build them, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/phong.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildPhong(const MaterialParameters& p) {
  return std::make_unique<PhongBsdf>(p.rgb("kd"), p.rgb("ks"), p.number("exponent"));
}

std::unique_ptr<BsdfModel> buildBlinnPhong(const MaterialParameters& p) {
  return std::make_unique<BlinnPhongBsdf>(p.rgb("kd"), p.rgb("ks"), p.number("exponent"));
}

}  // namespace

MaterialModel phongModel() {
  return {
      .type = "phong",
      .description =
          "Normalised (modified) Phong: kd/pi + ks (n+2)/(2pi) cos^n(mirror angle); kd + ks <= 1 "
          "conserves energy",
      .citation =
          "Lafortune & Willems 1994, Using the Modified Phong Reflectance Model for Physically Based "
          "Rendering, eq. 7",
      .parameters = {rgbParameter("kd", 0.5, "diffuse albedo per linear-RGB channel"),
                     rgbParameter("ks", 0.4, "specular albedo at normal incidence per linear-RGB channel"),
                     numberParameter("exponent", ValueRange::closed(0.0, 10000.0), 50.0, "Phong exponent n")},
      .alternatives = {},
      .build = buildPhong,
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false,
  };
}

MaterialModel blinnPhongModel() {
  return {
      .type = "blinn-phong",
      .description =
          "Normalised Blinn-Phong as Ngan et al. used it: kd/pi + ks (n+2)/(2pi) cos^n(theta_h); "
          "albedo up to about kd + 4 ks",
      .citation = "Ngan, Durand & Matusik 2005, Experimental Analysis of BRDF Models (Blinn-Phong variant)",
      .parameters = {rgbParameter("kd", 0.5, "diffuse albedo per linear-RGB channel"),
                     rgbParameter("ks", 0.1,
                                  "specular scale per linear-RGB channel (kd + 4 ks <= 1 keeps albedo <= 1)"),
                     numberParameter("exponent", ValueRange::closed(0.0, 100000.0), 100.0,
                                     "Blinn-Phong exponent n (Ngan's fits reach 67600)")},
      .alternatives = {},
      .build = buildBlinnPhong,
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false,
  };
}

}  // namespace scatterlab
