// What a material description's parameters may be: the declarative spec of one parameter
// (docs/design.md, "Material descriptions"), the validated values a build function reads, the
// error every bad description throws, and the words its messages are made of.
//
// Parsing and validation are generic over the spec (spec_validation.h), so an error always
// names the key, the value given and what is allowed, the same way for every model.
#pragma once

#include <array>
#include <initializer_list>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/core/math.h"

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

// The names of a pair parameter's two components: "alpha_x", "alpha_y".
std::array<std::string, 2> pairComponentNames(const ParameterSpec& spec);

// ---- Spec pieces that many models share.

// A number parameter with a default.
ParameterSpec numberParameter(std::string name, ValueRange range, double defaultValue,
                              std::string description);
// An rgb parameter in [0, 1] with a default: a reflectance or albedo per linear-RGB channel.
ParameterSpec rgbParameter(std::string name, double defaultValue, std::string description);
// Parameter lists joined in order, for models that share some of their parameters.
std::vector<ParameterSpec> joinParameters(std::initializer_list<std::vector<ParameterSpec>> parts);

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

// ---- Words for values and lists in error messages.

// "0.5", "inf", "NaN".
std::string formatNumber(double x);
// The value as JSON text, cut at 80 characters; NaN and infinities as such (json::dump writes
// them as null, which would hide the very value at fault).
std::string formatValue(const nlohmann::json& value);
std::string inQuotes(std::string_view text);
// "a", "a" and "b", ... joined with `separator`, each quoted.
std::string quotedList(const std::vector<std::string>& items, std::string_view separator = ", ");

// Throws the MaterialError every check of a key throws: "material key "KEY": VALUE PROBLEM;
// allowed: ALLOWED" (for builders that check what the spec alone cannot).
[[noreturn]] void throwMaterialKeyError(std::string_view key, const nlohmann::json& value,
                                        std::string_view problem, std::string_view allowed);

}  // namespace scatterlab
