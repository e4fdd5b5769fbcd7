// A material description checked against its model's spec (docs/design.md, "Material
// descriptions"): every key known, every value of the right kind and in range, alternatives
// given whole, nested materials validated in turn; then built (makeBsdf), completed with its
// defaults (completeMaterial) or made rougher for the roughness-mismatch negative control.
#pragma once

#include <cstdint>
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
// every default filled in, and the completed description. The typed value a material becomes
// once, where it is read; the builders and the negative controls below take it as it is, so a
// material is not validated again on its way through a command.
struct ValidatedMaterial {
  const MaterialModel* model = nullptr;
  MaterialParameters parameters;
  nlohmann::json completed;  // the material as given, plus every default that applies

  bool isSubsurface() const { return model->kind == MaterialKind::Subsurface; }
};
// Throws MaterialError on any invalid description (any kind of model).
ValidatedMaterial validateMaterial(const nlohmann::json& material);
// How many times validateMaterial has run in this process (top-level calls and nested
// materials alike): what the tests that follow one material through a command count.
uint64_t materialValidationCount();

// Checks a model's spec as a whole, as the validation of its materials relies on it: a type and
// parameter names that are present and distinct, every default a valid value of its parameter,
// sets of alternatives whose keys are parameters, a lobe-width parameter that is a number or pair parameter,
// a BSDF model with a build function. Throws MaterialError naming the model, the parameter and what is
// allowed. Every built-in model passes; a plugin's models are checked before they are added.
void checkModelSpec(const MaterialModel& model);

// A MaterialError of a nested material, re-keyed under `prefix` ("materials[1]"): "material
// key "alpha": ..." becomes "material key "materials[1].alpha": ...", and an error about the
// nested material as a whole ("material: ...") names the prefix as its key.
MaterialError nestedMaterialError(const MaterialError& error, const std::string& prefix);

// Builds the BSDF a material describes; throws MaterialError on any invalid description, and
// for a material that is not a BSDF (a subsurface material).
std::unique_ptr<BsdfModel> makeBsdf(const nlohmann::json& material);
std::unique_ptr<BsdfModel> makeBsdf(const ValidatedMaterial& material);

// The same material with every default filled in (validated; throws MaterialError), so that
// what is printed is exactly what was built.
nlohmann::json completeMaterial(const nlohmann::json& material);

// The material made `factor` (> 0) times rougher: its lobe-width parameter (MaterialModel::
// lobeWidthParameter) multiplied by `factor`, or divided by it for an exponent, and clamped to
// the allowed range, every default filled in; nullopt for models without one. The
// roughness-mismatch negative control samples from it.
std::optional<nlohmann::json> withScaledRoughness(const nlohmann::json& material, double factor);
std::optional<ValidatedMaterial> withScaledRoughness(const ValidatedMaterial& material, double factor);

// The material for the roughness-mismatch negative control: `factor` (> 1) times rougher, or
// as much smoother when the roughness is at its range limit (where scaling up would change
// nothing and the control would prove nothing); nullopt for models without a lobe width.
std::optional<nlohmann::json> withMismatchedRoughness(const nlohmann::json& material, double factor);
std::optional<ValidatedMaterial> withMismatchedRoughness(const ValidatedMaterial& material, double factor);

}  // namespace scatterlab
