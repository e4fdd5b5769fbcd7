// One model of the material registry: its declarative parameter spec and the function that
// builds it (docs/design.md, "Material descriptions"). Each model defines its entry beside its
// code (conductorModel() in materials/bsdf/conductor.cpp, ...); model_list.cpp lists them.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

using BuildBsdfFunction = std::unique_ptr<BsdfModel> (*)(const MaterialParameters&);
// Fills defaults that depend on other parameters (a subsurface medium's index of refraction)
// into the parameters and the completed description, and rejects combinations the spec alone
// cannot (throws MaterialError). Runs after every parameter has been validated.
using CompleteDependentFunction = void (*)(MaterialParameters&, nlohmann::json& completed);

// What a model builds: a BSDF (makeBsdf), or a subsurface material, a BSSRDF
// (materials/bssrdf/subsurface_registry.h, makeSubsurface). Both share the parameter specs
// and their validation.
enum class MaterialKind { Bsdf, Subsurface };

// One registry entry.
struct MaterialModel {
  std::string type{};
  MaterialKind kind = MaterialKind::Bsdf;
  std::string description{};  // one line
  std::string citation{};
  std::vector<ParameterSpec> parameters{};
  // Sets of keys that say the same thing in different ways (a conductor's "metal", or "eta"
  // with "k"). A material gives at most one set, and all of it; with none given, the first
  // set's defaults apply.
  std::vector<std::vector<std::string>> alternatives{};
  BuildBsdfFunction build = nullptr;  // Bsdf models
  CompleteDependentFunction completeDependent = nullptr;
  // The parameter that sets the width of the model's main lobe ("alpha", "sigma", a Phong
  // "exponent"), which withScaledRoughness scales for the roughness-mismatch negative
  // control; empty for models without one. An exponent narrows the lobe as it grows:
  // `widerWhenLarger` is false for it.
  std::string lobeWidthParameter{};
  bool widerWhenLarger = true;

  const ParameterSpec* findParameter(std::string_view name) const {
    const auto it = std::find_if(parameters.begin(), parameters.end(),
                                 [&](const ParameterSpec& p) { return p.name == name; });
    return it == parameters.end() ? nullptr : &*it;
  }
};

}  // namespace scatterlab
