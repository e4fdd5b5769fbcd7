#include "materials/registry/spec_validation.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <utility>

#include "materials/registry/model_list.h"
#include "materials/registry/plugin_bsdf.h"

namespace scatterlab {

namespace {

using nlohmann::json;

std::vector<std::string> modelTypes() {
  std::vector<std::string> types;
  for (const MaterialModel& model : materialModels()) types.push_back(model.type);
  return types;
}

// ---------------------------------------------------------------------------------------
// Generic parsing over a ParameterSpec.

// One real of a number, rgb or pair: finite and inside the spec's range. `whole` is the
// value as given (reported in the message); `component` names the entry of an array.
double parseComponent(const ParameterSpec& spec, const json& whole, const json& entry,
                      const std::string& component) {
  if (!entry.is_number()) throwMaterialKeyError(spec.name, whole, "has the wrong type", spec.allowed());
  const double x = entry.get<double>();
  const std::string where = component.empty() ? "" : " (" + component + " = " + formatNumber(x) + ")";
  if (!std::isfinite(x))
    throwMaterialKeyError(spec.name, whole, "is not a finite number" + where, spec.allowed());
  if (!spec.range.contains(x))
    throwMaterialKeyError(spec.name, whole, "is out of range" + where, spec.allowed());
  return x;
}

// A number broadcast to every component, or an array with one entry per component.
template <size_t N> std::array<double, N> parseComponents(const ParameterSpec& spec, const json& value,
                                                          const std::array<std::string, N>& componentNames) {
  std::array<double, N> out;
  if (value.is_number()) {
    out.fill(parseComponent(spec, value, value, ""));
    return out;
  }
  if (!value.is_array() || value.size() != N)
    throwMaterialKeyError(spec.name, value, "has the wrong type", spec.allowed());
  for (size_t i = 0; i < N; ++i) out[i] = parseComponent(spec, value, value[i], componentNames[i]);
  return out;
}

std::vector<json> parseNestedMaterials(const ParameterSpec& spec, const json& value) {
  if (!value.is_array() || value.size() != spec.materialCount)
    throwMaterialKeyError(spec.name, value,
                          value.is_array() ? "has the wrong number of materials" : "has the wrong type",
                          spec.allowed());
  thread_local int depth = 0;
  if (depth >= MaxMaterialNesting)
    throwMaterialKeyError(spec.name, value, "nests materials too deeply",
                          "at most " + std::to_string(MaxMaterialNesting) + " levels of nested materials");
  ++depth;
  struct Leave {
    ~Leave() { --depth; }
  } leave;
  std::vector<json> completed;
  for (size_t i = 0; i < value.size(); ++i) {
    try {
      completed.push_back(completeMaterial(value[i]));
    } catch (const MaterialError& error) {
      throw nestedMaterialError(error, spec.name + "[" + std::to_string(i) + "]");
    }
  }
  return completed;
}

ParameterValue parseValue(const ParameterSpec& spec, const json& value) {
  switch (spec.kind) {
    case ParameterKind::Number: return parseComponent(spec, value, value, "");
    case ParameterKind::Rgb: {
      const auto c = parseComponents<3>(spec, value, {"r", "g", "b"});
      return Rgb(c[0], c[1], c[2]);
    }
    case ParameterKind::Pair: {
      const auto c = parseComponents<2>(spec, value, pairComponentNames(spec));
      return Vec2d(c[0], c[1]);
    }
    case ParameterKind::Choice: {
      if (!value.is_string()) throwMaterialKeyError(spec.name, value, "has the wrong type", spec.allowed());
      const std::string& text = value.get_ref<const std::string&>();
      if (std::find(spec.choices.begin(), spec.choices.end(), text) == spec.choices.end())
        throwMaterialKeyError(spec.name, value, "is not one of the choices", spec.allowed());
      return text;
    }
    case ParameterKind::Path: {
      if (!value.is_string()) throwMaterialKeyError(spec.name, value, "has the wrong type", spec.allowed());
      if (value.get_ref<const std::string&>().empty())
        throwMaterialKeyError(spec.name, value, "is empty", spec.allowed());
      return value.get<std::string>();
    }
    case ParameterKind::Materials: return parseNestedMaterials(spec, value);
  }
  throw std::logic_error("unhandled parameter kind");
}

// ---------------------------------------------------------------------------------------
// Whole materials.

const MaterialModel& modelOf(const json& material) {
  if (!material.is_object())
    throw MaterialError("material: " + formatValue(material) +
                        " is not a JSON object; allowed: an object such as {\"type\": \"lambertian\"}");
  const auto type = material.find("type");
  const std::string allowedTypes = "one of " + quotedList(modelTypes());
  if (type == material.end())
    throw MaterialError("material key \"type\" is missing; allowed: " + allowedTypes);
  if (!type->is_string()) throwMaterialKeyError("type", *type, "has the wrong type", allowedTypes);
  const MaterialModel* model = findMaterialModel(type->get_ref<const std::string&>());
  if (!model) throwMaterialKeyError("type", *type, "is not a known model", allowedTypes);
  return *model;
}

void rejectUnknownKeys(const json& material, const MaterialModel& model) {
  for (const auto& [key, value] : material.items()) {
    if (key == "type" || model.findParameter(key)) continue;
    std::vector<std::string> keys{"type"};
    for (const ParameterSpec& spec : model.parameters) keys.push_back(spec.name);
    throw MaterialError("material key " + inQuotes(key) + " (value " + formatValue(value) +
                        ") is not a key of model " + inQuotes(model.type) + "; allowed: the keys " +
                        quotedList(keys));
  }
}

// "either "metal", or "eta" and "k" together"
std::string describeAlternatives(const MaterialModel& model) {
  std::string out = "either ";
  for (size_t i = 0; i < model.alternatives.size(); ++i) {
    const auto& keys = model.alternatives[i];
    out += (i ? ", or " : "") + quotedList(keys, " and ") + (keys.size() > 1 ? " together" : "");
  }
  return out;
}

// The first of `keys` that the material gives, or nullptr.
const std::string* firstGivenKey(const json& material, const std::vector<std::string>& keys) {
  const auto isGiven = [&](const std::string& key) { return material.contains(key); };
  const auto given = std::find_if(keys.begin(), keys.end(), isGiven);
  return given == keys.end() ? nullptr : &*given;
}

// The index into model.alternatives of the set of keys the material gives (at most one set,
// and all of it); 0, the default set, when it gives none.
size_t chosenAlternative(const json& material, const MaterialModel& model) {
  std::optional<size_t> chosen;
  for (size_t set = 0; set < model.alternatives.size(); ++set) {
    const std::string* given = firstGivenKey(material, model.alternatives[set]);
    if (!given) continue;
    if (chosen) {
      const std::string& other = *firstGivenKey(material, model.alternatives[*chosen]);
      throwMaterialKeyError(*given, material[*given], "cannot be combined with " + inQuotes(other),
                            describeAlternatives(model));
    }
    for (const std::string& key : model.alternatives[set])
      if (!material.contains(key))
        throwMaterialKeyError(*given, material[*given], "needs " + inQuotes(key) + " as well",
                              describeAlternatives(model));
    chosen = set;
  }
  return chosen.value_or(0);
}

bool isInUnchosenAlternative(const MaterialModel& model, size_t chosen, const std::string& name) {
  for (size_t set = 0; set < model.alternatives.size(); ++set) {
    if (set == chosen) continue;
    const auto& keys = model.alternatives[set];
    if (std::find(keys.begin(), keys.end(), name) != keys.end()) return true;
  }
  return false;
}

[[noreturn]] void throwSpecError(const MaterialModel& model, const std::string& problem,
                                 const std::string& allowed) {
  throw MaterialError("model " + inQuotes(model.type) + ": " + problem + "; allowed: " + allowed);
}

}  // namespace

void checkModelSpec(const MaterialModel& model) {
  if (model.type.empty() || model.type.find_first_of(" \t\n\"'{}[],:") != std::string::npos)
    throwSpecError(model, "the type is not a plain name",
                   "a non-empty name without spaces, quotes, brackets, commas or colons");
  if (model.kind == MaterialKind::Bsdf && !model.build)
    throwSpecError(model, "a BSDF model without a build function", "a build function");
  std::vector<std::string> names;
  for (const ParameterSpec& spec : model.parameters) {
    const std::string parameter = "parameter " + inQuotes(spec.name);
    if (spec.name.empty() || spec.name == "type")
      throwSpecError(model, "a parameter is named " + inQuotes(spec.name),
                     "a non-empty name other than \"type\"");
    if (std::find(names.begin(), names.end(), spec.name) != names.end())
      throwSpecError(model, parameter + " is listed twice", "distinct parameter names");
    names.push_back(spec.name);
    if (spec.kind == ParameterKind::Choice && spec.choices.empty())
      throwSpecError(model, parameter + " is a choice without choices", "at least one choice");
    // No default: required, in a set of alternatives, or derived by the build function (the
    // subsurface model's eta from its medium). A plugin's model has a default for every
    // parameter (checkPluginModel).
    if (spec.defaultValue.is_null()) continue;
    try {
      parseValue(spec, spec.defaultValue);
    } catch (const MaterialError& error) {
      throwSpecError(model, parameter + ": its default is not a valid value (" + error.what() + ")",
                     "a default the parameter accepts");
    }
  }
  for (const auto& keys : model.alternatives)
    for (const std::string& key : keys)
      if (!model.findParameter(key))
        throwSpecError(model, "the alternatives name " + inQuotes(key) + ", which is not a parameter",
                       "parameters of the model: " + quotedList(names));
  if (!model.lobeWidthParameter.empty()) {
    const ParameterSpec* width = model.findParameter(model.lobeWidthParameter);
    if (!width || (width->kind != ParameterKind::Number && width->kind != ParameterKind::Pair))
      throwSpecError(model,
                     "the lobe-width parameter " + inQuotes(model.lobeWidthParameter) +
                         " is not a number or pair parameter of the model",
                     "empty, or a number or pair parameter");
  }
}

MaterialError nestedMaterialError(const MaterialError& error, const std::string& prefix) {
  const std::string message = error.what();
  constexpr std::string_view KeyIntro = "material key \"";
  constexpr std::string_view WholeIntro = "material: ";
  if (message.starts_with(KeyIntro))
    return MaterialError(std::string(KeyIntro) + prefix + "." + message.substr(KeyIntro.size()));
  if (message.starts_with(WholeIntro))
    return MaterialError("material key " + inQuotes(prefix) + ": " + message.substr(WholeIntro.size()));
  return MaterialError("material key " + inQuotes(prefix) + ": " + message);
}

namespace {
std::atomic<uint64_t> validationCount{0};
}  // namespace

uint64_t materialValidationCount() { return validationCount.load(); }

ValidatedMaterial validateMaterial(const json& material) {
  ++validationCount;
  const MaterialModel& model = modelOf(material);
  rejectUnknownKeys(material, model);
  const size_t chosen = chosenAlternative(material, model);
  ValidatedMaterial parsed{&model, {}, json{{"type", model.type}}};
  for (const ParameterSpec& spec : model.parameters) {
    const auto given = material.find(spec.name);
    const bool useDefault = given == material.end();
    if (useDefault && spec.required)
      throw MaterialError("material key " + inQuotes(spec.name) + " is missing (model " +
                          inQuotes(model.type) + " needs it); allowed: " + spec.allowed());
    if (useDefault && (spec.defaultValue.is_null() || isInUnchosenAlternative(model, chosen, spec.name)))
      continue;
    const json& value = useDefault ? spec.defaultValue : *given;
    ParameterValue parsedValue = parseValue(spec, value);
    // Nested materials are completed too, so that what is printed is what is built.
    parsed.completed[spec.name] =
        spec.kind == ParameterKind::Materials ? json(std::get<std::vector<json>>(parsedValue)) : value;
    parsed.parameters.set(spec.name, std::move(parsedValue));
  }
  if (model.completeDependent) model.completeDependent(parsed.parameters, parsed.completed);
  return parsed;
}

std::unique_ptr<BsdfModel> makeBsdf(const ValidatedMaterial& parsed) {
  if (parsed.model->kind != MaterialKind::Bsdf || !parsed.model->build)
    throwMaterialKeyError(
        "type", parsed.model->type, "is a subsurface material (a BSSRDF), not a BSDF",
        "a BSDF model here; subsurface materials go to `scatterlab check`, `scatterlab profile` and "
        "`scatterlab render`");
  if (!parsed.model->plugin.empty()) return buildPluginBsdf(*parsed.model, parsed.parameters);
  return parsed.model->build(parsed.parameters);
}

std::unique_ptr<BsdfModel> makeBsdf(const nlohmann::json& material) {
  return makeBsdf(validateMaterial(material));
}

nlohmann::json completeMaterial(const nlohmann::json& material) {
  return validateMaterial(material).completed;
}

std::optional<ValidatedMaterial> withScaledRoughness(const ValidatedMaterial& material, double factor) {
  const MaterialModel& model = *material.model;
  if (model.lobeWidthParameter.empty()) return std::nullopt;
  const ParameterSpec* width = model.findParameter(model.lobeWidthParameter);
  if (!width || width->kind == ParameterKind::Choice || width->kind == ParameterKind::Rgb)
    throw std::logic_error("model \"" + model.type + "\": lobe-width parameter \"" +
                           model.lobeWidthParameter + "\" is not a number or pair parameter of the model");
  const double scale = model.widerWhenLarger ? factor : 1.0 / factor;
  ValidatedMaterial scaled = material;
  json& value = scaled.completed[model.lobeWidthParameter];
  if (value.is_array()) {
    for (json& component : value) component = width->range.clamp(component.get<double>() * scale);
  } else {
    value = width->range.clamp(value.get<double>() * scale);
  }
  // Clamped into the spec's range, so the parse cannot fail; it gives the typed value its form.
  scaled.parameters.set(width->name, parseValue(*width, value));
  return scaled;
}

std::optional<nlohmann::json> withScaledRoughness(const nlohmann::json& material, double factor) {
  auto scaled = withScaledRoughness(validateMaterial(material), factor);
  return scaled ? std::optional<json>(std::move(scaled->completed)) : std::nullopt;
}

std::optional<ValidatedMaterial> withMismatchedRoughness(const ValidatedMaterial& material, double factor) {
  auto rougher = withScaledRoughness(material, factor);
  if (!rougher || rougher->completed != material.completed) return rougher;
  return withScaledRoughness(material, 1.0 / factor);
}

std::optional<nlohmann::json> withMismatchedRoughness(const nlohmann::json& material, double factor) {
  auto mismatched = withMismatchedRoughness(validateMaterial(material), factor);
  return mismatched ? std::optional<json>(std::move(mismatched->completed)) : std::nullopt;
}

}  // namespace scatterlab
