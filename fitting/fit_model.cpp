#include "fitting/fit_model.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "materials/bsdf/metals.h"
#include "materials/core/json_text.h"
#include "materials/core/quoted.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::fitting {

namespace {

using nlohmann::json;

// A shape parameter: its registry key, how many kernel slots it fills (1 number, 3 rgb, 2 a
// pair fitted as one value) and how the initial grid spaces it.
struct ShapeInfo {
  const char* key;
  int slots = 1;
  GridSpacing spacing = GridSpacing::Linear;
  bool heldByDefault = false;    // held at its registry default unless given
  const char* tiedTo = nullptr;  // follows this shape unless either is given
  // A fitted quantity that is not a registry key (a conductor's f0 and edge tint): its range
  // and start, instead of the registry's.
  std::optional<ValueRange> ownRange = std::nullopt;
  double ownStart = 0;
};

// A linear term: the registry key of its scale ("scale": the blend weight of a model without
// one), and whether it is a diffuse term (held at 0 in repeated lobes).
struct TermInfo {
  const char* key;
  bool diffuse = false;
};

struct LobeInfo {
  const char* type;
  std::vector<TermInfo> terms;
  std::vector<ShapeInfo> shapes;
  FitKernelVariant (*kernel)(const json& completed);
  bool hasRest = false;  // the model has a part no linear term scales
};

constexpr const char* BlendWeightKey = "scale";

Rgb rgbValue(const json& value) {
  if (value.is_number()) return Rgb(value.get<double>());
  return Rgb(value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>());
}

template <typename K> FitKernelVariant plainKernel(const json&) { return K{}; }

FitKernelVariant eonKernel(const json& completed) {
  EonKernel k;
  k.albedoMode = completed.at("directional_albedo") == "analytic" ? EonAlbedo::Analytic : EonAlbedo::Fitted;
  return k;
}

FitKernelVariant lafortuneKernel(const json& completed) {
  LafortuneKernel k;
  k.normalization =
      completed.at("normalization") == "none" ? LafortuneNormalization::None : LafortuneNormalization::Ngan;
  return k;
}

FitKernelVariant conductorKernel(const json& completed) {
  Rgb eta = rgbValue(completed.at("eta")), k = rgbValue(completed.at("k"));
  if (completed.at("distribution") == "beckmann") {
    ConductorKernel<BeckmannDistribution> kernel;
    kernel.eta = eta;
    kernel.k = k;
    return kernel;
  }
  ConductorKernel<GgxDistribution> kernel;
  kernel.eta = eta;
  kernel.k = k;
  return kernel;
}

const std::vector<LobeInfo>& lobeInfos() {
  static const std::vector<LobeInfo> infos{
      {"lambertian", {{"albedo"}}, {}, plainKernel<LambertianKernel>},
      {"oren-nayar", {{"albedo"}}, {{"sigma"}}, plainKernel<OrenNayarKernel>},
      {"eon", {}, {{"albedo", 3}, {"roughness"}}, eonKernel, true},
      {"phong",
       {{"kd", true}, {"ks"}},
       {{"exponent", 1, GridSpacing::Log}},
       plainKernel<NormalizedPhongKernel<PhongLobe>>},
      {"blinn-phong",
       {{"kd", true}, {"ks"}},
       {{"exponent", 1, GridSpacing::Log}},
       plainKernel<NormalizedPhongKernel<BlinnPhongLobe>>},
      {"lafortune",
       {{"kd", true}, {"ks"}},
       {{"cx"}, {"cy", 1, GridSpacing::Linear, false, "cx"}, {"cz"}, {"exponent", 1, GridSpacing::Log}},
       lafortuneKernel},
      {"ward", {{"albedo"}}, {{"alpha", 2, GridSpacing::Log}}, plainKernel<WardKernel>},
      {"ngan-ward", {{"albedo"}}, {{"roughness", 1, GridSpacing::Log}}, plainKernel<NganWardKernel>},
      {"ashikhmin-shirley",
       {{"rd", true}},
       {{"exponent", 2, GridSpacing::Log}, {"rs", 3}},
       plainKernel<AshikhminShirleyKernel>,
       true},
      {"ngan-ashikhmin-shirley",
       {{"albedo"}},
       {{"fresnelReflectance"}, {"sharpness", 1, GridSpacing::Log}},
       plainKernel<NganAshikhminShirleyKernel>},
      {"ngan-cook-torrance",
       {{"albedo"}},
       {{"eta"}, {"roughness", 1, GridSpacing::Log}},
       plainKernel<NganCookTorranceKernel>},
      {"conductor", {{BlendWeightKey}}, {{"alpha", 2, GridSpacing::Log}}, conductorKernel},
      {"disney",
       {},
       {{"baseColor", 3},
        {"metallic"},
        {"subsurface"},
        {"specular"},
        {"specularTint"},
        {"roughness"},
        {"anisotropic", 1, GridSpacing::Linear, true},
        {"sheen"},
        {"sheenTint"},
        {"clearcoat"},
        {"clearcoatGloss"}},
       plainKernel<DisneyKernel>,
       true},
  };
  return infos;
}

FitKernelVariant pluginKernel(const json& completed) {
  ValidatedMaterial validated = validateMaterial(completed);
  return PluginModelKernel(*validated.model, std::move(validated.parameters));
}

// A plugin's model as the fitter sees it (plugin_model_kernel.h): every numeric parameter a
// shape, spaced in the log for its lobe width (an exponent or roughness spans decades), no
// linear terms. Made once per type; the registry's entries (and their names) never move.
const LobeInfo& pluginLobeInfo(const MaterialModel& model) {
  static std::mutex mutex;
  static std::deque<LobeInfo> infos;
  const std::lock_guard lock(mutex);
  for (const LobeInfo& info : infos)
    if (model.type == info.type) return info;
  LobeInfo info{model.type.c_str(), {}, {}, pluginKernel, true};
  for (const ParameterSpec& spec : model.parameters) {
    const int slots = spec.kind == ParameterKind::Number ? 1
                      : spec.kind == ParameterKind::Rgb  ? 3
                      : spec.kind == ParameterKind::Pair ? 2
                                                         : 0;
    if (slots == 0) continue;
    const bool logarithmic = spec.name == model.lobeWidthParameter && spec.range.max > 1;
    info.shapes.push_back({spec.name.c_str(), slots, logarithmic ? GridSpacing::Log : GridSpacing::Linear});
  }
  return infos.emplace_back(std::move(info));
}

FitKernelVariant fittedIndexConductorKernel(const json& completed) {
  if (completed.at("distribution") == "beckmann") return FittedIndexConductorKernel<BeckmannDistribution>{};
  return FittedIndexConductorKernel<GgxDistribution>{};
}

// A conductor that names neither "metal" nor "eta"/"k": its index is fitted as f0 and edge
// tint per channel (fit_model.h). f0 stays inside (0, 1), where the map to (eta, k) is finite
// and smooth; 0.001 and 0.999 are darker and brighter than any metal's reflectance in RGB.
const LobeInfo& fittedIndexConductorInfo() {
  static const LobeInfo info{
      "conductor",
      {},
      {{"alpha", 2, GridSpacing::Log},
       {"f0", 3, GridSpacing::Linear, false, nullptr, ValueRange::closed(0.001, 0.999), 0.5},
       {"edge_tint", 3, GridSpacing::Linear, false, nullptr, ValueRange::closed(0.0, 1.0), 0.5}},
      fittedIndexConductorKernel,
      true};
  return info;
}

bool namesNoIndex(const json& description) {
  return !description.contains("metal") && !description.contains("eta") && !description.contains("k");
}

const LobeInfo* findLobeInfo(const std::string& type) {
  for (const LobeInfo& info : lobeInfos())
    if (type == info.type) return &info;
  const MaterialModel* model = findMaterialModel(type);
  if (model && !model->plugin.empty() && model->kind == MaterialKind::Bsdf) return &pluginLobeInfo(*model);
  return nullptr;
}

// Why a plugin's model (that findLobeInfo accepts) cannot be fitted, or nothing.
std::optional<std::string> pluginRefusal(const MaterialModel& model, const json& completed) {
  const int slots = pluginModelSlots(model);
  if (slots == 0) return "it has no number, rgb or pair parameter to fit";
  if (slots > MaxSlots)
    return "its parameters take " + std::to_string(slots) + " numbers, the fitter at most " +
           std::to_string(MaxSlots);
  const LobeFlags flags = makeBsdf(completed)->flags();
  if (hasAny(flags, LobeFlags::Specular))
    return "it has delta (mirror) lobes, which have no BRDF values to compare with a table";
  if (hasAny(flags, LobeFlags::Transmission))
    return "it transmits light, which a reflection table does not constrain";
  return std::nullopt;
}

// Why a registry model cannot be fitted.
std::string refusal(const std::string& type) {
  if (type == "smooth-conductor" || type == "dielectric" || type == "thin-dielectric")
    return "its lobes are delta (mirror) lobes, which have no BRDF values to compare with a table";
  if (type == "rough-dielectric") return "it transmits light, which a reflection table does not constrain";
  if (type == "rough-plastic")
    return "its energy coupling reads precomputed albedo tables, which have no derivatives";
  if (type == "blend") return "sums of models are the fitter's own: give the components joined by '+'";
  if (type == "measured") return "it is a table of data, not a model with parameters";
  return "it is not a model of the registry";
}

std::string allowedModels() {
  std::string out = "one of ";
  const auto names = fittableModels();
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + inQuotes(names[i]);
  return out + ", joined by '+'";
}

// "lambertian+{...}" split at the '+' signs outside JSON objects, arrays and strings.
std::vector<std::string> splitTopLevel(const std::string& spec) {
  std::vector<std::string> parts(1);
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char ch : spec) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (ch == '\\')
        escaped = true;
      else if (ch == '"')
        inString = false;
    } else if (ch == '"') {
      inString = true;
    } else if (ch == '{' || ch == '[') {
      ++depth;
    } else if (ch == '}' || ch == ']') {
      --depth;
    } else if (ch == '+' && depth == 0) {
      parts.emplace_back();
      continue;
    }
    parts.back() += ch;
  }
  return parts;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

json parseComponentText(const std::string& text, const std::string& spec) {
  if (text.empty())
    throw MaterialError("model " + inQuotes(spec) + ": an empty component; allowed: " + allowedModels());
  if (text.front() != '{') return json{{"type", text}};
  try {
    return parseJsonText(text, "model component");
  } catch (const JsonTextError& error) {
    throw MaterialError("model component " + inQuotes(text) + ": not valid JSON (" + error.what() +
                        "); allowed: a registry type or a JSON object such as {\"type\": \"conductor\"}");
  }
}

double lowerBound(const ValueRange& range) {
  if (!std::isfinite(range.min)) return -1e300;
  return range.minOpen ? std::nextafter(range.min, range.max) : range.min;
}
double upperBound(const ValueRange& range) {
  if (!std::isfinite(range.max)) return 1e300;
  return range.maxOpen ? std::nextafter(range.max, range.min) : range.max;
}

const char* channelName(int c) { return c == 0 ? "r" : c == 1 ? "g" : "b"; }

// The value of `key` in a completed material as `slots` numbers (number, rgb or pair).
std::vector<double> slotValues(const json& value, int slots) {
  std::vector<double> out(static_cast<size_t>(slots));
  for (int i = 0; i < slots; ++i)
    out[size_t(i)] = value.is_number() ? value.get<double>() : value.at(size_t(i)).get<double>();
  return out;
}

}  // namespace

std::vector<std::string> fittableModels() {
  std::vector<std::string> names;
  for (const LobeInfo& info : lobeInfos()) names.emplace_back(info.type);
  for (const MaterialModel& model : materialModels())
    if (!model.plugin.empty() && model.kind == MaterialKind::Bsdf) names.push_back(model.type);
  return names;
}

std::vector<std::string> FitModel::derivativeNotes() const {
  std::vector<std::string> notes;
  for (const FitComponent& comp : components_)
    if (const auto* plugin = std::get_if<PluginModelKernel>(&comp.kernel);
        plugin && plugin->numericDerivatives())
      notes.push_back("model component \"" + comp.label + "\": numeric derivatives (central differences of " +
                      "the model's eval): its plugin (" + plugin->model().plugin +
                      ") registers no fit kernel (fitting/plugin_fit_kernel.h gives exact ones)");
  return notes;
}

std::vector<json> parseModelSpec(const std::string& spec, int lobes) {
  if (lobes < 1 || lobes > 3) throw std::invalid_argument("lobes must be in [1, 3]");
  const std::string text = trimmed(spec);
  std::vector<json> components;
  if (!text.empty() && text.front() == '[') {
    json array;
    try {
      array = parseJsonText(text, "model");
    } catch (const JsonTextError& error) {
      throw MaterialError("model " + inQuotes(text) + ": not valid JSON (" + error.what() +
                          "); allowed: an array of material objects, or types joined by '+'");
    }
    if (array.empty())
      throw MaterialError("model " + inQuotes(text) + ": no components; allowed: " + allowedModels());
    for (const json& part : array) components.push_back(part);
  } else {
    for (const std::string& part : splitTopLevel(text))
      components.push_back(parseComponentText(trimmed(part), text));
  }
  for (int i = 1; i < lobes; ++i) components.push_back(components.back());
  return components;
}

FitModel::FitModel(const std::vector<json>& descriptions, bool perChannelShape)
    : perChannelShape_(perChannelShape) {
  if (descriptions.empty()) throw MaterialError("model: no components; allowed: " + allowedModels());
  std::map<std::string, int> count, seen;
  for (const json& d : descriptions)
    if (d.is_object() && d.contains("type") && d["type"].is_string()) ++count[d["type"].get<std::string>()];
  for (size_t i = 0; i < descriptions.size(); ++i) {
    const json& d = descriptions[i];
    std::string label = "component " + std::to_string(i + 1);
    bool repeated = false;
    if (d.is_object() && d.contains("type") && d["type"].is_string()) {
      const std::string type = d["type"].get<std::string>();
      const int k = ++seen[type];
      label = count[type] > 1 ? type + "#" + std::to_string(k) : type;
      repeated = k > 1;
    }
    addComponent(d, label, repeated);
  }
  for (const FitComponent& comp : components_) {
    if (comp.fittedIndex && components_.size() > 1)
      throw MaterialError(
          "model component " + inQuotes(comp.label) +
          ": a conductor whose index is fitted (no \"metal\", \"eta\" or \"k\") carries its whole "
          "value in its Fresnel factor and can only be fitted alone; allowed: \"conductor\" by "
          "itself, a conductor with a given index, or a white specular lobe with a fitted RGB scale, "
          "{\"type\":\"conductor\",\"eta\":1,\"k\":1e8}");
    if (comp.hasRest && components_.size() > 1)
      throw MaterialError(
          "model component " + inQuotes(comp.label) +
          ": a model with no linear scale of its whole value (eon, disney, ashikhmin-shirley) can "
          "only be fitted alone; allowed: that model by itself, or models with an albedo joined by '+'");
  }
}

void FitModel::addComponent(const json& description, const std::string& label, bool repeated) {
  if (!description.is_object() || !description.contains("type") || !description["type"].is_string())
    throw MaterialError("model " + label + ": " + description.dump() +
                        " is not a material object with a \"type\"; allowed: " + allowedModels());
  const std::string type = description["type"].get<std::string>();
  const LobeInfo* info = findLobeInfo(type);
  if (!info) {
    if (!findMaterialModel(type))
      throw MaterialError("model component " + inQuotes(type) +
                          " is not a known model; allowed: " + allowedModels());
    throw MaterialError("model component " + inQuotes(type) + " cannot be fitted: " + refusal(type) +
                        "; allowed: " + allowedModels());
  }
  const bool fittedIndex = type == "conductor" && namesNoIndex(description);
  if (fittedIndex) info = &fittedIndexConductorInfo();
  json completed;
  try {
    completed = completeMaterial(description);
  } catch (const MaterialError& error) {
    throw MaterialError("model component " + inQuotes(label) + ": " + error.what());
  }
  if (fittedIndex) completed.erase("metal");  // the default metal: the fit replaces it by (eta, k)
  if (type == "conductor" && completed.value("multiscatter", "none") != "none")
    throw MaterialError("model component " + inQuotes(label) + ": \"multiscatter\": \"" +
                        completed["multiscatter"].get<std::string>() +
                        "\" cannot be fitted (its compensation reads albedo tables); allowed: \"none\"");
  if (type == "conductor" && completed.contains("metal")) {
    const MetalIor* metal = findMetal(completed["metal"].get<std::string>());
    completed["eta"] = {metal->eta.x, metal->eta.y, metal->eta.z};
    completed["k"] = {metal->k.x, metal->k.y, metal->k.z};
    completed.erase("metal");
  }
  const MaterialModel& registry = *findMaterialModel(type);
  if (!registry.plugin.empty())
    if (const auto why = pluginRefusal(registry, completed))
      throw MaterialError("model component " + inQuotes(type) + " cannot be fitted: " + *why +
                          "; allowed: a plugin model with 1 to " + std::to_string(MaxSlots) +
                          " numeric values that only reflects");

  FitComponent comp;
  comp.label = label;
  comp.type = type;
  comp.description = completed;
  comp.kernel = info->kernel(completed);
  comp.fittedIndex = fittedIndex;
  comp.hasRest = info->hasRest;
  comp.terms = int(info->terms.size());
  comp.scalable = !info->hasRest;
  for (auto& e : comp.slotParameter) e.fill(-1);
  for (auto& t : comp.termParameter) t.fill(-1);

  const size_t componentIndex = components_.size();
  const auto addParameter = [&](const std::string& key, int channel, ParameterRole role,
                                const ValueRange& range, double start, GridSpacing spacing) {
    FitParameter p;
    p.name = label + "." + key + (channel >= 0 ? std::string(".") + channelName(channel) : "");
    p.component = componentIndex;
    p.key = key;
    p.channel = channel;
    p.role = role;
    p.lower = lowerBound(range);
    p.upper = upperBound(range);
    p.start = std::clamp(start, p.lower, p.upper);
    p.spacing = spacing;
    parameters_.push_back(p);
    return int(parameters_.size() - 1);
  };

  for (size_t j = 0; j < info->terms.size(); ++j) {
    const TermInfo& term = info->terms[j];
    comp.termKeys[j] = term.key;
    const bool isBlendWeight = std::string(term.key) == BlendWeightKey;
    if (isBlendWeight) comp.scalable = false;
    const bool held = !isBlendWeight && description.contains(term.key);
    if (held || (repeated && term.diffuse)) {
      comp.heldTerm[j] = held ? rgbValue(completed[term.key]) : Rgb(0.0);
      continue;
    }
    const ValueRange range =
        isBlendWeight ? ValueRange::closed(0.0, 1.0) : registry.findParameter(term.key)->range;
    const Rgb start = isBlendWeight ? Rgb(0.5) : rgbValue(completed[term.key]);
    for (int c = 0; c < 3; ++c)
      comp.termParameter[j][size_t(c)] =
          addParameter(term.key, c, ParameterRole::Scale, range, start[c], GridSpacing::Linear);
  }

  // Shape parameters: slots in the kernel's order.
  std::map<std::string, std::array<int, 3>> fittedShape;  // key -> parameter per evaluation
  std::map<std::string, int> firstSlot;
  int slot = 0;
  bool anyPerChannel = false;
  for (const ShapeInfo& shape : info->shapes) {
    firstSlot[shape.key] = slot;
    comp.shapeLayout.push_back({shape.key, slot, shape.slots});
    const bool given = description.contains(shape.key);
    const bool tieGiven = shape.tiedTo && description.contains(shape.tiedTo);
    const std::vector<double> values = shape.ownRange
                                           ? std::vector<double>(size_t(shape.slots), shape.ownStart)
                                           : slotValues(completed.at(shape.key), shape.slots);
    for (int i = 0; i < shape.slots; ++i) comp.heldSlot[size_t(slot + i)] = values[size_t(i)];
    if (given || shape.heldByDefault) {
      slot += shape.slots;
      continue;
    }
    if (shape.tiedTo && !tieGiven && fittedShape.count(shape.tiedTo)) {
      for (int e = 0; e < 3; ++e)
        comp.slotParameter[size_t(e)][size_t(slot)] = fittedShape[shape.tiedTo][size_t(e)];
      slot += shape.slots;
      continue;
    }
    const ValueRange range = shape.ownRange ? *shape.ownRange : registry.findParameter(shape.key)->range;
    if (!registry.plugin.empty() && !(std::isfinite(range.min) && std::isfinite(range.max)))
      throw MaterialError("model component " + inQuotes(label) + ": parameter " + inQuotes(shape.key) +
                          " has an unbounded range (" + range.describe() +
                          "), which the fitter's grid cannot cover; allowed: give it a value to hold it");
    std::array<int, 3> perEvaluation{};
    if (shape.slots == 3) {
      // An RGB shape: one parameter per channel, read by every evaluation.
      for (int c = 0; c < 3; ++c) {
        const int index =
            addParameter(shape.key, c, ParameterRole::Shape, range, values[size_t(c)], shape.spacing);
        for (int e = 0; e < 3; ++e) comp.slotParameter[size_t(e)][size_t(slot + c)] = index;
      }
      perEvaluation.fill(-1);
    } else {
      if (perChannelShape_) {
        anyPerChannel = true;
        for (int c = 0; c < 3; ++c)
          perEvaluation[size_t(c)] =
              addParameter(shape.key, c, ParameterRole::Shape, range, values[0], shape.spacing);
      } else {
        perEvaluation.fill(
            addParameter(shape.key, -1, ParameterRole::Shape, range, values[0], shape.spacing));
      }
      for (int e = 0; e < 3; ++e)
        for (int i = 0; i < shape.slots; ++i)
          comp.slotParameter[size_t(e)][size_t(slot + i)] = perEvaluation[size_t(e)];
    }
    fittedShape[shape.key] = perEvaluation;
    slot += shape.slots;
  }
  comp.slots = slot;
  comp.perChannel = anyPerChannel;
  components_.push_back(std::move(comp));
}

std::vector<FittedPart> FitModel::fittedParts(const double* x) const {
  std::vector<FittedPart> parts;
  for (const FitComponent& comp : components_) {
    const int evaluations = comp.perChannel ? 3 : 1;
    for (int e = 0; e < evaluations; ++e) {
      const auto mask = [&](int c) { return !comp.perChannel || c == e ? 1.0 : 0.0; };
      FittedPart part;
      part.material = comp.description;
      const auto slotValue = [&](int slot) {
        const int index = comp.slotParameter[size_t(e)][size_t(slot)];
        return index >= 0 ? x[index] : comp.heldSlot[size_t(slot)];
      };
      for (const FitComponent::ShapeLayout& shape : comp.shapeLayout) {
        if (shape.slotCount == 1) {
          part.material[shape.key] = slotValue(shape.firstSlot);
          continue;
        }
        json values = json::array();
        for (int i = 0; i < shape.slotCount; ++i) values.push_back(slotValue(shape.firstSlot + i));
        part.material[shape.key] = values;
      }
      if (comp.fittedIndex) {
        // f0 and edge tint -> the (eta, k) the registry conductor takes.
        json eta = json::array(), k = json::array();
        for (int c = 0; c < 3; ++c) {
          const ComplexIndexT<double> index =
              indexFromReflectanceAndEdgeTint(part.material.at("f0").at(size_t(c)).get<double>(),
                                              part.material.at("edge_tint").at(size_t(c)).get<double>());
          eta.push_back(index.eta);
          k.push_back(index.k);
        }
        part.material.erase("f0");
        part.material.erase("edge_tint");
        part.material["eta"] = eta;
        part.material["k"] = k;
      }
      part.scalable = comp.scalable;
      for (int j = 0; j < comp.terms; ++j) {
        Rgb value;
        for (int c = 0; c < 3; ++c) {
          const int index = comp.termParameter[size_t(j)][size_t(c)];
          value[c] = mask(c) * (index >= 0 ? x[index] : comp.heldTerm[size_t(j)][c]);
        }
        if (comp.termKeys[size_t(j)] == BlendWeightKey) {
          part.weight = value;
          continue;
        }
        part.material[comp.termKeys[size_t(j)]] = {value.x, value.y, value.z};
        part.scaleKeys.push_back(comp.termKeys[size_t(j)]);
      }
      if (!comp.scalable && comp.termKeys[0] != BlendWeightKey) part.weight = Rgb(mask(0), mask(1), mask(2));
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

std::vector<double> FitModel::startValues() const {
  std::vector<double> x;
  for (const FitParameter& p : parameters_) x.push_back(p.start);
  return x;
}

std::vector<size_t> FitModel::parametersOf(ParameterRole role) const {
  std::vector<size_t> out;
  for (size_t i = 0; i < parameters_.size(); ++i)
    if (parameters_[i].role == role) out.push_back(i);
  return out;
}

void FitModel::evaluateTerms(const double* x, const Vec3d& wi, const Vec3d& wo,
                             std::vector<std::array<Rgb, MaxTerms>>& terms, std::vector<Rgb>& rests) const {
  terms.resize(components_.size());
  rests.resize(components_.size());
  for (size_t k = 0; k < components_.size(); ++k) {
    const FitComponent& comp = components_[k];
    std::visit(
        [&](const auto& kernel) {
          using Kernel = std::decay_t<decltype(kernel)>;
          const int evaluations = comp.perChannel ? 3 : 1;
          if constexpr (std::is_same_v<Kernel, PluginModelKernel>) {
            // No linear terms: the whole value is the rest.
            for (int e = 0; e < evaluations; ++e) {
              std::array<double, MaxSlots> slots{};
              for (int i = 0; i < kernel.slots(); ++i) {
                const int index = comp.slotParameter[size_t(e)][size_t(i)];
                slots[size_t(i)] = index >= 0 ? x[index] : comp.heldSlot[size_t(i)];
              }
              double value[3];
              kernel.eval(slots.data(), wi, wo, value, nullptr);
              const int cBegin = comp.perChannel ? e : 0, cEnd = comp.perChannel ? e + 1 : 3;
              for (int c = cBegin; c < cEnd; ++c) rests[k][c] = value[c];
            }
          } else {
            for (int e = 0; e < evaluations; ++e) {
              std::array<double, MaxSlots> slots{};
              for (int i = 0; i < Kernel::Slots; ++i) {
                const int index = comp.slotParameter[size_t(e)][size_t(i)];
                slots[size_t(i)] = index >= 0 ? x[index] : comp.heldSlot[size_t(i)];
              }
              std::array<Rgb, MaxTerms> t{};
              Rgb rest;
              kernel.eval(slots.data(), wi, wo, t.data(), rest);
              const int cBegin = comp.perChannel ? e : 0, cEnd = comp.perChannel ? e + 1 : 3;
              for (int c = cBegin; c < cEnd; ++c) {
                for (int j = 0; j < Kernel::Terms; ++j) terms[k][size_t(j)][c] = t[size_t(j)][c];
                rests[k][c] = rest[c];
              }
            }
          }
        },
        comp.kernel);
  }
}

}  // namespace scatterlab::fitting
