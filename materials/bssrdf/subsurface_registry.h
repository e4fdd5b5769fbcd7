// The registry entry of subsurface materials (docs/design.md, "Material descriptions"):
//   {"type": "subsurface", "profile": "burley", "medium": "Skin1", "scale": 1.0}
// It shares the BSDF registry's parameter specs and validation (materials/registry/: every error names
// the key, the value and what is allowed), is listed by `scatterlab models` with the BSDFs
// (kind "subsurface"), and is built by makeSubsurface rather than makeBsdf.
#pragma once

#include <memory>

#include <nlohmann/json.hpp>

#include "materials/bssrdf/subsurface_material.h"
#include "materials/registry/material_model.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

// The "subsurface" entry for materialModels().
MaterialModel subsurfaceMaterialModel();

// True when `material` is an object whose type is a subsurface model (no other validation).
bool isSubsurfaceMaterial(const nlohmann::json& material);

// Builds the subsurface material a description gives; throws MaterialError on any invalid
// description, and for a BSDF description.
SubsurfaceMaterial makeSubsurface(const nlohmann::json& material);
SubsurfaceMaterial makeSubsurface(const ValidatedMaterial& material);

// The BSDF of any registry material as seen from afar: a BSDF material's own BSDF (makeBsdf), a
// subsurface material's BSSRDF integrated over the entry point (subsurface_far_field_brdf.h).
// What `scatterlab eval` and the explorer evaluate; throws MaterialError on any invalid
// description.
std::unique_ptr<BsdfModel> makeFarFieldBsdf(const nlohmann::json& material);

}  // namespace scatterlab
