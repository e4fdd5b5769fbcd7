// The material registry: builds every BSDF model from its JSON description and describes
// every model's parameters for `scatterlab models` (docs/design.md, "Material descriptions").
//
// Each model is one entry: a declarative parameter spec and a build function. Parsing and
// validation are generic over the spec, so an error always names the key, the value given
// and what is allowed, the same way for every model, and adding a model touches nothing but
// its entry in registry.cpp.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

// A material description that cannot be built. The message names the key, the value given
// and what is allowed, so that it can be shown to the user as it is.
class MaterialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// number: a real; rgb: a number (all channels) or [r, g, b]; pair: a number (both) or
// [x, y]; choice: one string out of a list; path: a file path (in a material file, relative
// to that file's directory: loadMaterialArgument resolves it); materials: an array of
// materialCount material objects, each validated as a material of its own (a blend's
// components; errors name the nested key, "materials[1].alpha").
enum class ParameterKind { Number, Rgb, Pair, Choice, Path, Materials };
std::string toString(ParameterKind kind);

// The values a number (or every component of an rgb or pair) may take. Either end may be
// open or infinite.
struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minOpen = false;
  bool maxOpen = false;

  static ValueRange closed(double lo, double hi) { return {lo, hi, false, false}; }
  static ValueRange above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, true}; }
  static ValueRange atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, true}; }

  bool contains(double x) const;
  // The nearest value inside the range (open ends: the nearest representable value inside).
  double clamp(double x) const;
  // "in [0.001, 1]", "> 0", ">= 0".
  std::string describe() const;
};

struct ParameterSpec {
  std::string name{};
  ParameterKind kind = ParameterKind::Number;
  ValueRange range{};                  // Number, Rgb, Pair
  std::vector<std::string> choices{};  // Choice
  // null when the parameter has no default: it is then one of the alternatives of another
  // parameter (a conductor's "eta" and "k" instead of "metal") and absent unless given.
  nlohmann::json defaultValue{};
  std::string description{};
  // No default and no alternative: a material without it is an error (a measured file).
  bool required = false;
  size_t materialCount = 0;  // Materials: how many nested materials

  // What the parameter accepts, in words: "a number or [alpha_x, alpha_y], each in [0.001, 1]".
  std::string allowed() const;
};

// A parameter's value after validation, in the form its kind describes.
// Materials: the nested materials, validated and completed (built by the build function).
using ParameterValue = std::variant<double, Rgb, Vec2d, std::string, std::vector<nlohmann::json>>;

// The validated parameters of one material, every default filled in. Build functions read
// them by name; the spec guarantees that a parameter with a default is always present.
class MaterialParameters {
 public:
  void set(const std::string& name, ParameterValue value) {
    values_.insert_or_assign(name, std::move(value));
  }
  bool has(std::string_view name) const { return values_.find(name) != values_.end(); }
  // Asking for a parameter the spec does not provide, or as another kind, is a bug in the
  // build function: std::logic_error.
  double number(std::string_view name) const;
  Rgb rgb(std::string_view name) const;
  Vec2d pair(std::string_view name) const;
  const std::string& choice(std::string_view name) const;
  const std::string& path(std::string_view name) const;
  const std::vector<nlohmann::json>& materials(std::string_view name) const;

 private:
  template <typename T> const T& get(std::string_view name) const;

  std::map<std::string, ParameterValue, std::less<>> values_;
};

// Choices backed by enums: the spec's list of strings and the build function's lookup come
// from one table, so the two cannot drift apart.
template <typename E> struct NamedChoice {
  const char* name;
  E value;
};

template <typename E, size_t N>
std::vector<std::string> choiceNames(const std::array<NamedChoice<E>, N>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.name);
  return names;
}

// The spec has already checked that `name` is one of the table's names.
template <typename E, size_t N>
E choiceValue(const std::array<NamedChoice<E>, N>& table, std::string_view name) {
  for (const auto& entry : table)
    if (name == entry.name) return entry.value;
  throw std::logic_error("choice \"" + std::string(name) + "\" missing from its table");
}

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

  const ParameterSpec* findParameter(std::string_view name) const;
};

// Every model, in the order `scatterlab models` lists them.
std::span<const MaterialModel> materialModels();
const MaterialModel* findMaterialModel(std::string_view type);

// The catalog as JSON: [{type, description, citation, parameters: [{name, kind, allowed,
// min, max, min_open, max_open, choices, default, description}], alternatives}].
nlohmann::json materialCatalogJson();

// A material description validated against its model's spec: the model, the parameters with
// every default filled in, and the completed description.
struct ValidatedMaterial {
  const MaterialModel* model = nullptr;
  MaterialParameters parameters;
  nlohmann::json completed;  // the material as given, plus every default that applies
};
// Throws MaterialError on any invalid description (any kind of model).
ValidatedMaterial validateMaterial(const nlohmann::json& material);

// Throws the MaterialError every check of a key throws: "material key "KEY": VALUE PROBLEM;
// allowed: ALLOWED" (for builders that check what the spec alone cannot).
[[noreturn]] void throwMaterialKeyError(std::string_view key, const nlohmann::json& value,
                                        std::string_view problem, std::string_view allowed);

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

// Calls `visit` with the value of every path parameter (a non-empty string) of `material` and of
// the materials nested in it, at any depth; `visit` may replace it (a measured material's "file"
// made relative to a directory, or pointed at a copy).
void forEachPathParameter(nlohmann::json& material, const std::function<void(nlohmann::json& path)>& visit);

// True when a material argument is inline JSON rather than a file path.
bool isInlineMaterial(std::string_view argument);

// Parses a material argument: inline JSON when it starts with '{', a file path otherwise.
// Throws MaterialError naming the file (not found, not readable) or the source and position
// of a parse error. The result is not validated; makeBsdf/completeMaterial do that. From a
// file, relative values of path parameters (a measured material's "file"), at any depth, are
// made relative to the file's directory, so a material file and its data can move together.
nlohmann::json loadMaterialArgument(const std::string& argument);

}  // namespace scatterlab
