// The material registry's one list of models: what `scatterlab models` lists, what material
// descriptions are validated against, and what a test that covers every model iterates
// (docs/design.md, "Material descriptions").
#pragma once

#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "materials/registry/material_model.h"

namespace scatterlab {

// Every model, in the order `scatterlab models` lists them.
std::span<const MaterialModel> materialModels();
const MaterialModel* findMaterialModel(std::string_view type);

// The catalog as JSON: [{type, description, citation, parameters: [{name, kind, allowed,
// min, max, min_open, max_open, choices, default, description}], alternatives}].
nlohmann::json materialCatalogJson();

}  // namespace scatterlab
