// One material of a lab report: what it is, built once, with everything its sections need.
// From the command line a MATERIAL is inline JSON, a JSON file, or a measured file: a MERL table
// or an RGL .bsdf file (told by content: materials/measured/measured_file.h), short for
// {"type": "measured", "file": PATH}.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"
#include "materials/bssrdf/subsurface_material.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

enum class LabMaterialKind { Analytic, Measured, Subsurface };
const char* toString(LabMaterialKind kind);

struct LabMaterial {
  std::string name;    // shown in the report; unique in a report
  std::string folder;  // its images and data.json: a file-system-safe, unique name
  std::string about;   // one sentence: what it is and where it came from
  LabMaterialKind kind = LabMaterialKind::Analytic;
  nlohmann::json description;                    // completed: every default filled in
  std::optional<ValidatedMaterial> validated;    // Analytic and Subsurface: the typed description
  std::unique_ptr<BsdfModel> bsdf;               // Analytic and Measured
  std::shared_ptr<const MerlTable> table;        // Measured MERL table: the table as stored
  const RglBrdf* rgl = nullptr;                  // Measured RGL file: the model (owned by bsdf)
  std::optional<SubsurfaceMaterial> subsurface;  // Subsurface
  // Measured-style tables made by the lab: the models whose sum the table holds (a published
  // fit's Lambertian and lobe), shown as the ground truth next to the fits.
  std::vector<nlohmann::json> groundTruth;
};

// Loads a command-line MATERIAL (see above). Throws MaterialError (an invalid description, a
// bad MERL file: the message names the file or key and what is allowed).
LabMaterial loadLabMaterial(const std::string& argument);

// A measured material from a table already in memory (the showcase's generated tables).
LabMaterial measuredLabMaterial(std::string name, const std::filesystem::path& file,
                                std::shared_ptr<const MerlTable> table);

// A measured material from an RGL file; throws MaterialError naming the file and field.
LabMaterial rglLabMaterial(std::string name, const std::filesystem::path& file);

// Any registry material (analytic or subsurface) under a name.
LabMaterial describedLabMaterial(std::string name, const nlohmann::json& material);

// Gives materials with the same name a numbered suffix and every material a unique folder.
void makeNamesUnique(std::vector<LabMaterial>& materials);

}  // namespace scatterlab
