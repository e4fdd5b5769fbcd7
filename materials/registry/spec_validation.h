// A material description checked against its model's spec (docs/design.md, "Material
// descriptions"): every key known, every value of the right kind and in range, alternatives
// given whole, nested materials validated in turn; then built (makeBsdf), completed with its
// defaults (completeMaterial) or made rougher for the roughness-mismatch negative control.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

// Blends of blends are fine; a description nested deeper than this is a mistake (or an attack
// on the stack), not a material.
constexpr int MaxMaterialNesting = 8;

// A material description validated against its model's spec: the model, the parameters with
// every default filled in, and the completed description.
struct ValidatedMaterial {
  const MaterialModel* model = nullptr;
  MaterialParameters parameters;
  nlohmann::json completed;  // the material as given, plus every default that applies
};
// Throws MaterialError on any invalid description (any kind of model).
ValidatedMaterial validateMaterial(const nlohmann::json& material);

// A MaterialError of a nested material, re-keyed under `prefix` ("materials[1]"): "material
// key "alpha": ..." becomes "material key "materials[1].alpha": ...", and an error about the
// nested material as a whole ("material: ...") names the prefix as its key.
MaterialError nestedMaterialError(const MaterialError& error, const std::string& prefix);

// Builds the BSDF a material describes; throws MaterialError on any invalid description, and
// for a material that is not a BSDF (a subsurface material).
std::unique_ptr<BsdfModel> makeBsdf(const nlohmann::json& material);

// The same material with every default filled in (validated; throws MaterialError), so that
// what is printed is exactly what was built.
nlohmann::json completeMaterial(const nlohmann::json& material);

// The material made `factor` (> 0) times rougher: its lobe-width parameter (MaterialModel::
// lobeWidthParameter) multiplied by `factor`, or divided by it for an exponent, and clamped to
// the allowed range, every default filled in; nullopt for models without one. The
// roughness-mismatch negative control samples from it.
std::optional<nlohmann::json> withScaledRoughness(const nlohmann::json& material, double factor);

// The material for the roughness-mismatch negative control: `factor` (> 1) times rougher, or
// as much smoother when the roughness is at its range limit (where scaling up would change
// nothing and the control would prove nothing); nullopt for models without a lobe width.
std::optional<nlohmann::json> withMismatchedRoughness(const nlohmann::json& material, double factor);

}  // namespace scatterlab
