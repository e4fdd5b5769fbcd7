// The material registry's "smooth-conductor" model (smooth_conductor.h): its parameter spec and the function
// that builds it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/smooth_conductor.h"

#include <memory>

#include "materials/bsdf/conductor_index_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildSmoothConductor(const MaterialParameters& p) {
  const ConductorIndex index = conductorIndex(p);
  return std::make_unique<SmoothConductorBsdf>(index.eta, index.k);
}

}  // namespace

MaterialModel smoothConductorModel() {
  return {
      .type = "smooth-conductor",
      .description = "Polished metal: a perfect mirror (delta lobe) with the exact conductor Fresnel",
      .citation =
          "Fresnel equations for a complex index (Born & Wolf, Principles of Optics, section 14.2); "
          "pbrt-v4 ConductorBxDF, smooth case",
      .parameters = conductorIndexParameters(),
      .alternatives = conductorIndexAlternatives(),
      .build = buildSmoothConductor,
      .losslessExamples = {{{"type", "smooth-conductor"}, {"eta", {1, 1, 1}}, {"k", {1e8, 1e8, 1e8}}}},
  };
}

}  // namespace scatterlab
