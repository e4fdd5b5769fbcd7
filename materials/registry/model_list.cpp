#include "materials/registry/model_list.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "materials/bsdf/ashikhmin_shirley.h"
#include "materials/bsdf/blend.h"
#include "materials/bsdf/conductor.h"
#include "materials/bsdf/cook_torrance.h"
#include "materials/bsdf/disney.h"
#include "materials/bsdf/eon.h"
#include "materials/bsdf/lafortune.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/oren_nayar.h"
#include "materials/bsdf/phong.h"
#include "materials/bsdf/rough_dielectric.h"
#include "materials/bsdf/rough_plastic.h"
#include "materials/bsdf/smooth_conductor.h"
#include "materials/bsdf/smooth_dielectric.h"
#include "materials/bsdf/thin_dielectric.h"
#include "materials/bsdf/ward.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/measured/measured_file.h"

namespace scatterlab {

using nlohmann::json;

namespace {

// The one explicit list of built-in models. Each model's spec and build function live beside
// its code (`MaterialModel conductorModel()` in materials/bsdf/conductor.cpp, declared in its
// header): adding a model is its own file plus one line here. Parsing, validation and the
// catalog are generic over the entries.
std::deque<MaterialModel>& modelList() {
  static std::deque<MaterialModel> models{lambertianModel(),
                                          conductorModel(),
                                          smoothConductorModel(),
                                          dielectricModel(),
                                          thinDielectricModel(),
                                          roughDielectricModel(),
                                          roughPlasticModel(),
                                          blendModel(),
                                          orenNayarModel(),
                                          eonModel(),
                                          phongModel(),
                                          blinnPhongModel(),
                                          lafortuneModel(),
                                          wardModel(),
                                          nganWardModel(),
                                          ashikhminShirleyModel(),
                                          nganAshikhminShirleyModel(),
                                          nganCookTorranceModel(),
                                          disneyModel(),
                                          measuredModel(),
                                          subsurfaceMaterialModel()};
  return models;
}

}  // namespace

const std::deque<MaterialModel>& materialModels() { return modelList(); }

void addMaterialModel(MaterialModel model) {
  if (const MaterialModel* existing = findMaterialModel(model.type))
    throw MaterialError(
        "model type " + inQuotes(model.type) + " already exists (" +
        (existing->plugin.empty() ? std::string("built in") : "from plugin " + existing->plugin) +
        "); allowed: a type no other model has");
  modelList().push_back(std::move(model));
}

const MaterialModel* findMaterialModel(std::string_view type) {
  const auto& models = materialModels();
  const auto it =
      std::find_if(models.begin(), models.end(), [&](const MaterialModel& m) { return m.type == type; });
  return it == models.end() ? nullptr : &*it;
}

nlohmann::json materialCatalogJson() {
  json catalog = json::array();
  for (const MaterialModel& model : materialModels()) {
    json parameters = json::array();
    for (const ParameterSpec& spec : model.parameters) {
      json entry{{"name", spec.name},
                 {"kind", toString(spec.kind)},
                 {"allowed", spec.allowed()},
                 {"default", spec.defaultValue},
                 {"description", spec.description}};
      if (spec.kind == ParameterKind::Choice) {
        entry["choices"] = spec.choices;
      } else if (spec.kind == ParameterKind::Materials) {
        entry["count"] = spec.materialCount;
      } else if (spec.kind != ParameterKind::Path) {
        // JSON has no infinity: an unbounded end is null.
        entry["min"] = std::isfinite(spec.range.min) ? json(spec.range.min) : json();
        entry["max"] = std::isfinite(spec.range.max) ? json(spec.range.max) : json();
        entry["min_open"] = spec.range.minOpen;
        entry["max_open"] = spec.range.maxOpen;
      }
      parameters.push_back(std::move(entry));
    }
    catalog.push_back({{"type", model.type},
                       {"kind", model.kind == MaterialKind::Bsdf ? "bsdf" : "subsurface"},
                       {"description", model.description},
                       {"citation", model.citation},
                       {"parameters", std::move(parameters)},
                       {"alternatives", model.alternatives}});
    if (!model.plugin.empty()) catalog.back()["plugin"] = model.plugin;
  }
  return catalog;
}

}  // namespace scatterlab
