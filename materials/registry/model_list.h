// The material registry's one list of models: what `scatterlab models` lists, what material
// descriptions are validated against, and what a test that covers every model iterates
// (docs/design.md, "Material descriptions"). The built-in models are listed explicitly in
// model_list.cpp; plugins (materials/registry/plugin.h) append theirs at run time, before any
// material is read.
#pragma once

#include <deque>
#include <string_view>

#include <nlohmann/json.hpp>

#include "materials/registry/material_model.h"

namespace scatterlab {

// Every model, in the order `scatterlab models` lists them: the built-in ones, then those
// plugins added. A deque, so that adding a model never moves the others (ValidatedMaterial and
// callers keep pointers to entries).
const std::deque<MaterialModel>& materialModels();
const MaterialModel* findMaterialModel(std::string_view type);

// Appends a model loaded at run time (a plugin's, checked by checkPluginModel in plugin.h).
// Throws MaterialError when a model of that type exists. Not thread-safe: models are added at
// start-up, before anything reads the list.
void addMaterialModel(MaterialModel model);

// The catalog as JSON: [{type, description, citation, parameters: [{name, kind, allowed,
// min, max, min_open, max_open, choices, default, description}], alternatives}], and for a
// plugin's model "plugin": the library's path.
nlohmann::json materialCatalogJson();

}  // namespace scatterlab
