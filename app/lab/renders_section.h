// The renders of a material's report: its sphere path-traced (integrator/render.h) under each
// of the report's environment maps, the material alone on the preview scene (the ground, the
// contact shadow and, for a transparent material, the caustic under the first map and the
// scene's sphere light) and, for a measured material, each family's fit rendered
// the same way beside it with the difference |material - fit| (PNG to look at, linear EXR and
// renders.json with the numbers beside it). Every render of one environment uses the same
// seed, so material and fit share their random numbers (common random numbers) and the
// difference image shows the models' difference more than the noise; the variance of each
// pixel's mean (RenderSettings::varianceLayer) gives the noise level the difference is
// compared with.
//
// Which materials are rendered is the renderer's decision, not the report's: every material
// description (the material's own and every fit's) goes to the integrator's
// makeMaterialScene (integrator/material_scene.h), and one it refuses is shown in the report
// with the renderer's message where its picture would be. No type is special-cased here, so a
// material the renderer learns to render (subsurface materials, for instance) appears in the
// report without a change in this file.
//
// Samples the film drops (not finite or negative, integrator/render.h) are counted per render
// and shown in a red box at the top of the section (data: "dropped_samples"); the lab fails
// the material when there are any.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/lab/fit_section.h"
#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/report_section.h"
#include "integrator/environment.h"
#include "integrator/scene.h"

namespace scatterlab {

struct LabEnvironment {
  std::string name;  // the file's stem: "studio"
  std::string file;
  Environment environment;
  nlohmann::json description;  // file, size, clamped negative values
};

// The environment maps a report uses when --env is not given: two of data/envmaps (an
// interior with soft light, an exterior with a sun), installed beside the executable
// (app/data_directory.h).
std::vector<std::string> defaultLabEnvironmentFiles();

// Reads and checks each map (integrator/environment_map_file.h). A missing, unreadable or
// invalid map throws InputError naming --env and the file.
std::vector<LabEnvironment> loadLabEnvironments(const std::vector<std::string>& files);

// The scene of one material description under an environment, `size` x `size` pixels. The
// report uses the integrator's material sphere (integratorSphereScene); tests give others.
using SphereSceneFactory =
    std::function<Scene(const nlohmann::json& material, const Environment& environment, int size)>;
SphereSceneFactory integratorSphereScene();
// The material on the integrator's preview scene (integrator/scene_presets.h), width x height.
using PreviewSceneFactory = std::function<Scene(const nlohmann::json& material,
                                                const Environment& environment, int width, int height)>;
PreviewSceneFactory integratorPreviewScene();

// Renders `material` (and the families of `fits`, when given) under every environment and
// writes the images into `materialDir`. A description the factory refuses (MaterialError, or
// RenderInputError) is rendered as the factory's message.
ReportSection rendersSection(const LabMaterial& material, const MaterialFits* fits,
                             const LabSettings& settings, const std::vector<LabEnvironment>& environments,
                             const std::filesystem::path& materialDir, const ProgressCallback& progress,
                             const SphereSceneFactory& sceneOf = integratorSphereScene(),
                             const PreviewSceneFactory& previewOf = integratorPreviewScene());

// The fit whose renders are closest to the material's (smallest mean over the maps of the
// relative mean |material - fit|), with that difference per map: "Lambert + GGX: 1.5%
// (studio), 5.1% (courtyard)"; empty without fits.
std::string closestFitInRenders(const ReportSection& renders);

// Each fit's relative mean |material - fit| on the sphere per map, "1.5% (studio), 5.1%
// (courtyard)", by fit name; empty without fits.
std::map<std::string, std::string> fitRenderDifferences(const ReportSection& renders);

// The report's sentence for a material the renderer refused (empty when it rendered): the
// section's data "refused" entry of the material itself.
std::string renderRefusal(const ReportSection& renders);

}  // namespace scatterlab
