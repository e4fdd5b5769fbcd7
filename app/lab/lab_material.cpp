#include "app/lab/lab_material.h"

#include <set>

#include "app/json_output.h"
#include "app/lab/report_page.h"
#include "app/lab/staged_directory.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/quoted.h"
#include "materials/measured/measured_file.h"
#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"
#include "validation/chi_square_images.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

LabMaterial loadMeasured(std::string name, const fs::path& file) {
  try {
    return measuredLabMaterial(std::move(name), file, std::make_shared<const MerlTable>(readMerl(file)));
  } catch (const MerlError& error) {
    throw MaterialError(measuredFileProblem(error.what()));
  }
}

// A MERL table or an RGL file, told apart by content.
LabMaterial loadMeasuredFile(std::string name, const fs::path& file) {
  return isTensorFile(file) ? rglLabMaterial(std::move(name), file) : loadMeasured(std::move(name), file);
}

LabMaterial fromDescription(const std::string& name, const json& material) {
  // A measured description goes through the registry's validation, then the file is read
  // once and kept (its slices and fits need the data itself, not only the model).
  if (material.is_object() && material.value("type", std::string()) == "measured") {
    const json completed = completeMaterial(material);
    LabMaterial loaded = loadMeasuredFile(name, completed.at("file").get<std::string>());
    loaded.description = completed;
    return loaded;
  }
  return describedLabMaterial(name, material);
}

}  // namespace

const char* toString(LabMaterialKind kind) {
  switch (kind) {
    case LabMaterialKind::Analytic: return "analytic";
    case LabMaterialKind::Measured: return "measured";
    case LabMaterialKind::Subsurface: return "subsurface";
  }
  return "analytic";
}

LabMaterial measuredLabMaterial(std::string name, const fs::path& file,
                                std::shared_ptr<const MerlTable> table) {
  LabMaterial m;
  m.name = std::move(name);
  m.kind = LabMaterialKind::Measured;
  m.description = json{{"type", "measured"}, {"file", file.string()}};
  m.bsdf = std::make_unique<TabulatedBrdf>(*table);
  m.table = std::move(table);
  m.about = "MERL table " + file.string();
  return m;
}

LabMaterial rglLabMaterial(std::string name, const fs::path& file) {
  std::unique_ptr<RglBrdf> brdf;
  try {
    brdf = readRglBrdf(file);
  } catch (const TensorFileError& error) {
    throw MaterialError(measuredFileProblem(error.what()));
  }
  LabMaterial m;
  m.name = std::move(name);
  m.kind = LabMaterialKind::Measured;
  m.description = json{{"type", "measured"}, {"file", file.string()}};
  m.rgl = brdf.get();
  m.about =
      "RGL measured BRDF " + file.string() + (brdf->description().empty() ? "" : ": " + brdf->description());
  m.bsdf = std::move(brdf);
  return m;
}

LabMaterial describedLabMaterial(std::string name, const json& material) {
  LabMaterial m;
  m.name = std::move(name);
  // Validated once; the builders and the negative control take the typed value.
  m.validated = validateMaterial(material);
  m.description = m.validated->completed;
  if (m.validated->isSubsurface()) {
    m.kind = LabMaterialKind::Subsurface;
    m.subsurface = makeSubsurface(*m.validated);
  } else {
    m.kind = LabMaterialKind::Analytic;
    m.bsdf = makeBsdf(*m.validated);
  }
  m.about = jsonText(m.description, -1);
  return m;
}

LabMaterial loadLabMaterial(const std::string& argument) {
  if (!isInlineMaterial(argument) && measuredFormatOf(argument))
    return loadMeasuredFile(fs::path(argument).stem().string(), argument);
  const json material = loadMaterialArgument(argument);
  if (isInlineMaterial(argument)) {
    const std::string type =
        material.is_object() ? material.value("type", std::string("material")) : "material";
    LabMaterial loaded = fromDescription(type, material);
    loaded.about = "Given as inline JSON: " + jsonText(material, -1);
    return loaded;
  }
  try {
    LabMaterial loaded = fromDescription(fs::path(argument).stem().string(), material);
    loaded.about = "file " + argument + ": " + jsonText(loaded.description, -1);
    return loaded;
  } catch (const MaterialError& error) {
    throw MaterialError("material file " + inQuotes(argument) + ": " + error.what());
  }
}

void makeNamesUnique(std::vector<LabMaterial>& materials) {
  // The report's own entries (report_page.h, staged_directory.h) are no material's folder: a
  // material file called assets.json or index.html.json must not overwrite them.
  std::set<std::string> names,
      folders{"assets", "index.html", ReportMarkerFile, DirectoryManifestFile, "scratch"};
  for (LabMaterial& material : materials) {
    const std::string base = material.name;
    for (int copy = 2; !names.insert(material.name).second; ++copy)
      material.name = base + " #" + std::to_string(copy);
    // Never empty and never starting with '.': no "..", no hidden folder.
    std::string folderBase = safeFileStem(material.name);
    if (folderBase.empty() || folderBase.front() == '.') folderBase = "material" + folderBase;
    material.folder = folderBase;
    for (int copy = 2; !folders.insert(material.folder).second; ++copy)
      material.folder = folderBase + "-" + std::to_string(copy);
  }
}

}  // namespace scatterlab
