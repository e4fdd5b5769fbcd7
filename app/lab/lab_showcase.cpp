#include "app/lab/lab_showcase.h"

#include <memory>

#include "app/data_directory.h"
#include "app/measured_bundle.h"
#include "app/synth_command.h"
#include "app/table_cache.h"
#include "materials/core/temporary_files.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/ngan_fits.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

MeasurementPerturbation showcasePerturbation() {
  MeasurementPerturbation p;
  p.gainSigma = 0.0;  // no gain error: the published fit stays the ground truth of every channel
  p.logSigma = 0.05;
  p.noiseFloor = 1e-4;
  p.missingAboveDeg = 85.0;
  p.seed = 1;
  return p;
}

json perturbationJson(const MeasurementPerturbation& p) {
  return {{"seed", p.seed},
          {"gain_sigma", p.gainSigma},
          {"log_noise", p.logSigma},
          {"noise_floor", p.noiseFloor},
          {"missing_above_deg", p.missingAboveDeg ? json(*p.missingAboveDeg) : json()}};
}

const BundleMaterial& bundleMaterial(const std::string& name) {
  for (const BundleMaterial& material : measuredBundle())
    if (name == material.name) return material;
  throw std::logic_error("no bundle material " + name);
}

// The table of a published fit line with the showcase's perturbation: from the cache when it
// holds it, else synthesised (all cores) and written there.
std::shared_ptr<const MerlTable> measuredStyleTable(TableCache& cache, const BundleMaterial& material,
                                                    const MeasurementPerturbation& perturbation,
                                                    const ProgressCallback& progress) {
  const json source{{"fit_file", BundleFitFile},
                    {"fit", material.fitLine},
                    {"perturbation", perturbationJson(perturbation)}};
  if (cache.holds(material.name, source))
    return std::make_shared<const MerlTable>(readMerl(cache.file(material.name)));
  std::vector<std::unique_ptr<BsdfModel>> models;
  std::vector<const BsdfModel*> components;
  for (const json& component : parsePublishedFitLine(material.fitLine).components()) {
    models.push_back(makeBsdf(component));
    components.push_back(models.back().get());
  }
  const MeasurementSynthesizer synthesizer(components, perturbation);
  auto table = std::make_shared<const MerlTable>(synthesizeTable(synthesizer, 0, progress));
  writeMerl(cache.file(material.name), *table);
  cache.record(material.name, material.category, source);
  return table;
}

LabMaterial measuredStyle(TableCache& cache, const std::string& name, const std::string& what,
                          const ProgressCallback& progress) {
  const BundleMaterial& material = bundleMaterial(name);
  const MeasurementPerturbation perturbation = showcasePerturbation();
  LabMaterial m = measuredLabMaterial(name, cache.file(name),
                                      measuredStyleTable(cache, material, perturbation, progress));
  m.groundTruth = parsePublishedFitLine(material.fitLine).components();
  for (json& component : m.groundTruth) component = completeMaterial(component);
  m.about = "Measured-style " + what +
            ": a MERL-layout table synthesised from the published Ngan et al. 2005 "
            "Cook-Torrance fit of MERL's " +
            name +
            ", with 5% log-normal noise, a 1e-4 noise floor and no "
            "measurements beyond 85 degrees (" +
            cache.file(name).string() + ")";
  return m;
}

}  // namespace

std::optional<fs::path> showcaseCacheDirectory() {
  const auto cache = defaultCacheDirectory();
  return cache ? std::optional(*cache / "lab-showcase") : std::nullopt;
}

std::vector<LabMaterial> showcaseLabMaterials(const fs::path& scratch, PhaseTimer& timer,
                                              const ProgressCallback& progress) {
  std::vector<LabMaterial> materials;
  materials.push_back(describedLabMaterial(
      "gold-ggx", json{{"type", "conductor"}, {"distribution", "ggx"}, {"alpha", 0.2}, {"metal", "Au"}}));
  materials.back().about =
      "Analytic conductor: GGX microfacets (alpha 0.2), gold's complex index of refraction";
  materials.push_back(describedLabMaterial(
      "red-rough-plastic",
      json{{"type", "rough-plastic"}, {"alpha", 0.15}, {"diffuse", {0.6, 0.08, 0.05}}, {"eta", 1.5}}));
  materials.back().about =
      "Plastic: a rough dielectric coating (GGX alpha 0.15, eta 1.5) over a red Lambertian base";

  timer.time("synth", "", [&] {
    fs::path directory = showcaseCacheDirectory().value_or(scratch);
    std::error_code error;
    createDirectoriesUninterrupted(directory, error);
    if (error || !fs::is_directory(directory))
      directory = scratch;  // an unwritable cache is no reason to fail
    createDirectoriesUninterrupted(directory);
    TableCache cache(directory);
    materials.push_back(measuredStyle(cache, "gold-metallic-paint", "paint", progress));
    materials.push_back(measuredStyle(cache, "alum-bronze", "metal", progress));
  });

  // Two real measurements of the RGL database (data/rgl, CC0).
  const fs::path rgl = runtimeDataDirectory("the lab's RGL showcase materials") / "rgl";
  materials.push_back(rglLabMaterial("rgl-ibiza-sunset-vinyl", rgl / "cc_ibiza_sunset_rgb.bsdf"));
  materials.back().about =
      "Real measurement (RGL database, Dupuy & Jakob 2018): TeckWrap vinyl wrapping film \"Ibiza Sunset\", a "
      "glossy coloured film; isotropic, RGB (data/rgl/cc_ibiza_sunset_rgb.bsdf)";
  materials.push_back(rglLabMaterial("rgl-green-acrylic-felt", rgl / "acrylic_felt_green_rgb.bsdf"));
  materials.back().about =
      "Real measurement (RGL database, Dupuy & Jakob 2018): green acrylic felt, a rough fabric; isotropic, "
      "RGB "
      "(data/rgl/acrylic_felt_green_rgb.bsdf)";

  materials.push_back(describedLabMaterial(
      "skin-burley", json{{"type", "subsurface"}, {"profile", "burley"}, {"medium", "Skin1"}}));
  materials.back().about =
      "Subsurface: Christensen-Burley normalised diffusion for Jensen et al. 2001's Skin1 "
      "(searchlight fit), against the half-space random walk in the same medium";
  makeNamesUnique(materials);
  return materials;
}

}  // namespace scatterlab
