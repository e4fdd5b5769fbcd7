#include "materials/registry/parameter_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace scatterlab {

using nlohmann::json;

// ---------------------------------------------------------------------------------------
// Words for values and lists in error messages.

std::string formatNumber(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// json::dump writes NaN and infinities as null, which would hide the very value at fault.
std::string formatValue(const json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    return formatNumber(value.get<double>());
  if (value.is_array()) {
    std::string out = "[";
    // Appended piece by piece: "," + formatValue(...) trips GCC 12's -Wstringop-overflow once
    // formatValue is not file-local (a false positive like the one inQuotes avoids).
    for (size_t i = 0; i < value.size(); ++i) {
      if (i) out += ',';
      out += formatValue(value[i]);
    }
    return out + "]";
  }
  constexpr size_t MaxLength = 80;
  std::string text = value.dump();
  if (text.size() > MaxLength) text = text.substr(0, MaxLength - 3) + "...";
  return text;
}

std::string inQuotes(std::string_view text) {
  // Appended piece by piece: "\"" + std::string(text) + "\"" trips GCC 12's -Wrestrict (a
  // false positive, GCC bug 105329).
  std::string out(1, '"');
  out += text;
  out += '"';
  return out;
}

std::string quotedList(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? std::string(separator) : "") + inQuotes(items[i]);
  return out;
}

void throwMaterialKeyError(std::string_view key, const json& value, std::string_view problem,
                           std::string_view allowed) {
  throw MaterialError("material key " + inQuotes(key) + ": " + formatValue(value) + " " +
                      std::string(problem) + "; allowed: " + std::string(allowed));
}

// ---------------------------------------------------------------------------------------
// The spec.

std::string toString(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::Number: return "number";
    case ParameterKind::Rgb: return "rgb";
    case ParameterKind::Pair: return "pair";
    case ParameterKind::Choice: return "choice";
    case ParameterKind::Path: return "path";
    case ParameterKind::Materials: return "materials";
  }
  return "unknown";
}

bool ValueRange::contains(double x) const {
  const bool aboveMin = minOpen ? x > min : x >= min;
  const bool belowMax = maxOpen ? x < max : x <= max;
  return aboveMin && belowMax;
}

double ValueRange::clamp(double x) const {
  const double lo = minOpen ? std::nextafter(min, max) : min;
  const double hi = maxOpen ? std::nextafter(max, min) : max;
  return std::clamp(x, lo, hi);
}

std::string ValueRange::describe() const {
  const bool boundedBelow = std::isfinite(min), boundedAbove = std::isfinite(max);
  if (boundedBelow && boundedAbove)
    return "in " + std::string(minOpen ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) +
           (maxOpen ? ")" : "]");
  if (boundedBelow) return (minOpen ? "> " : ">= ") + formatNumber(min);
  if (boundedAbove) return (maxOpen ? "< " : "<= ") + formatNumber(max);
  return "finite";
}

std::array<std::string, 2> pairComponentNames(const ParameterSpec& spec) {
  return {spec.name + "_x", spec.name + "_y"};
}

std::string ParameterSpec::allowed() const {
  switch (kind) {
    case ParameterKind::Number: return "a number " + range.describe();
    case ParameterKind::Rgb: return "a number or [r, g, b], each " + range.describe();
    case ParameterKind::Pair: {
      const auto names = pairComponentNames(*this);
      return "a number or [" + names[0] + ", " + names[1] + "], each " + range.describe();
    }
    case ParameterKind::Choice: return "one of " + quotedList(choices);
    case ParameterKind::Path: return "a file path (in a material file: relative to that file's directory)";
    case ParameterKind::Materials:
      return "an array of exactly " + std::to_string(materialCount) +
             " materials, each a material object of any type such as {\"type\": \"lambertian\"}";
  }
  return "";
}

ParameterSpec numberParameter(std::string name, ValueRange range, double defaultValue,
                              std::string description) {
  return {.name = std::move(name),
          .kind = ParameterKind::Number,
          .range = range,
          .defaultValue = defaultValue,
          .description = std::move(description)};
}

ParameterSpec rgbParameter(std::string name, double defaultValue, std::string description) {
  return {.name = std::move(name),
          .kind = ParameterKind::Rgb,
          .range = ValueRange::closed(0.0, 1.0),
          .defaultValue = defaultValue,
          .description = std::move(description)};
}

std::vector<ParameterSpec> joinParameters(std::initializer_list<std::vector<ParameterSpec>> parts) {
  std::vector<ParameterSpec> joined;
  for (const auto& part : parts) joined.insert(joined.end(), part.begin(), part.end());
  return joined;
}

// ---------------------------------------------------------------------------------------
// Validated values.

template <typename T> const T& MaterialParameters::get(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end() || !std::holds_alternative<T>(it->second))
    throw std::logic_error("material parameter \"" + std::string(name) +
                           "\" read as a kind its spec does not give");
  return std::get<T>(it->second);
}

double MaterialParameters::number(std::string_view name) const { return get<double>(name); }
Rgb MaterialParameters::rgb(std::string_view name) const { return get<Rgb>(name); }
Vec2d MaterialParameters::pair(std::string_view name) const { return get<Vec2d>(name); }
const std::string& MaterialParameters::choice(std::string_view name) const { return get<std::string>(name); }
const std::string& MaterialParameters::path(std::string_view name) const { return get<std::string>(name); }
const std::vector<nlohmann::json>& MaterialParameters::materials(std::string_view name) const {
  return get<std::vector<nlohmann::json>>(name);
}

}  // namespace scatterlab
