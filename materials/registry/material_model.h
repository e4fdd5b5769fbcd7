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

// A model's BRDF value as a function of its numeric parameters, for the fitter when the model is
// none of its own kernels (fitting/lobe_kernels.h): a plugin's templated kernel instantiated with
// automatic derivatives by fitting/plugin_fit_kernel.h. The slots are the model's number (1),
// rgb (3) and pair (2) parameters in the order of its spec.
struct FitKernelFunction {
  int slots = 0;
  // value[c] = f_c(slots; wi, wo) without the cosine (the model's eval); when `gradient` is not
  // null, also gradient[c * slots + i] = d value[c] / d slots[i].
  void (*eval)(const double* slots, const Vec3d& wi, const Vec3d& wo, double value[3],
               double* gradient) = nullptr;

  explicit operator bool() const { return eval != nullptr; }
};

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
  // Where the model comes from: empty for a built-in model, the library's path for a plugin's
  // (materials/registry/plugin.h); makeBsdf then guards its calls (plugin_bsdf.h).
  std::string plugin{};
  // Optional, for plugin models: the fitter's kernel (without one it differentiates numerically).
  FitKernelFunction fitKernel{};
  // Materials of this model that are lossless by construction (BsdfModel::isLossless()), one per
  // way the model can be: the white-furnace render test renders every one of them
  // (tests/integrator/furnace_test.cpp). Empty for a model that never is.
  std::vector<nlohmann::json> losslessExamples{};

  const ParameterSpec* findParameter(std::string_view name) const {
    const auto it = std::find_if(parameters.begin(), parameters.end(),
                                 [&](const ParameterSpec& p) { return p.name == name; });
    return it == parameters.end() ? nullptr : &*it;
  }
};

}  // namespace scatterlab
