// The example's model as a scatterlab plugin (materials/registry/plugin.h): registered as type
// "example-phong" with parameters "exponent" and "ks", so that
//
//     scatterlab check  --plugin libexample_phong.so '{"type": "example-phong"}' --negative-controls
//     scatterlab lab    --plugin libexample_phong.so '{"type": "example-phong", "exponent": 80}'
//     scatterlab render --plugin libexample_phong.so '{"type": "example-phong"}' --out phong
//     scatterlab fit    --plugin libexample_phong.so '{"type": "example-phong", "exponent": 80}'
//                       --model example-phong --metric l2
//
// work as for a built-in model: the spec gives the ranges, defaults and error messages.
#include <memory>

#include "example_phong.h"
#include "fitting/plugin_fit_kernel.h"
#include "materials/registry/plugin.h"

// The deliberately broken build of this file defines it as 1.1 (CMakeLists.txt).
#ifndef EXAMPLE_PHONG_PDF_EXPONENT_SCALE
#define EXAMPLE_PHONG_PDF_EXPONENT_SCALE 1.0
#endif

namespace {

using namespace scatterlab;

std::unique_ptr<BsdfModel> buildExamplePhong(const MaterialParameters& parameters) {
  return std::make_unique<own_bsdf::ExamplePhong>(parameters.rgb("ks"), parameters.number("exponent"),
                                                  EXAMPLE_PHONG_PDF_EXPONENT_SCALE);
}

// For `scatterlab fit`: f over the spec's numeric parameters in order (exponent, then ks's three
// channels), templated so that the fitter gets exact derivatives (ceres::Jet). Optional: without
// it the fitter differentiates numerically, and says so.
struct ExamplePhongKernel {
  static constexpr int Slots = 4;
  template <typename T> static RgbT<T> eval(const T* slots, const Vec3d& wi, const Vec3d& wo) {
    return own_bsdf::examplePhongValue(RgbT<T>(slots[1], slots[2], slots[3]), slots[0], wi, wo);
  }
};

void registerModels(PluginRegistrar& registrar) {
  registrar.addModel({
      .type = "example-phong",
      .description = "Example plugin: normalised Phong lobe ks (n+2)/(2pi) cos^n(mirror angle); ks <= 1 "
                     "conserves energy",
      .citation = "Lafortune & Willems 1994, Using the Modified Phong Reflectance Model for Physically Based "
                  "Rendering, eq. 7",
      .parameters = {numberParameter("exponent", ValueRange::closed(0.0, 10000.0), 30.0, "Phong exponent n"),
                     rgbParameter("ks", 0.8, "specular albedo at normal incidence per linear-RGB channel")},
      .build = buildExamplePhong,
      // The roughness-mismatch negative control samples from an exponent 10% off; a larger
      // exponent is a narrower lobe.
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false,
      .fitKernel = fitting::fitKernelFunction<ExamplePhongKernel>(),
  });
}

}  // namespace

SCATTERLAB_PLUGIN(registerModels)
