#include "app/render_command.h"

#include <charconv>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/option_values.h"
#include "app/output_guard.h"
#include "app/plugin_option.h"
#include "app/progress.h"
#include "app/staged_outputs.h"
#include "integrator/contact_sheet.h"
#include "integrator/environment_map_file.h"
#include "integrator/exr_io.h"
#include "integrator/material_scene.h"
#include "integrator/png_io.h"
#include "integrator/render.h"
#include "integrator/render_error.h"
#include "integrator/scene_presets.h"
#include "integrator/silhouette_mask.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/quoted.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A render whose film dropped samples (not finite, or negative: render.h) has written its
// images, with those samples as 0, and fails: exit 1, as a material that fails a check.
int droppedSampleStatus(uint64_t droppedSamples) {
  return static_cast<int>(droppedSamples == 0 ? ExitCode::Success : ExitCode::CheckFailed);
}

// The line that names what the film dropped, for stderr; empty when nothing was.
std::string droppedSampleMessage(const std::string& label, const RenderStatistics& stats) {
  if (stats.droppedSamples() == 0) return "";
  return "render: " + label + ": " + std::to_string(stats.droppedSamples()) + " of " +
         std::to_string(stats.samples) + " samples dropped (" + std::to_string(stats.nonFiniteSamples) +
         " not finite, " + std::to_string(stats.negativeSamples) +
         " negative): the material returned values that no light transport produces; they count as 0 "
         "in the image\n";
}

std::optional<int> parsePositive(const std::string& text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || value < 1) return std::nullopt;
  return value;
}

const std::string ResolutionAllowed = "WxH (or N for N x N), each side in [1, " +
                                      std::to_string(MaxImageSide) + "] and at most " +
                                      std::to_string(MaxImagePixels) + " pixels, e.g. 256x256";

CLI::Validator resolutionValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parseResolution(text)
                   ? ""
                   : inQuotes(text) + " is not a valid resolution; allowed: " + ResolutionAllowed;
      },
      "WxH");
}

struct MaterialToRender {
  std::string label;
  json completed;
  RenderableMaterial material;
};

std::string defaultLabel(const std::string& argument, const json& material) {
  if (!isInlineMaterial(argument)) return fs::path(argument).stem().string();
  return material.value("type", std::string("material"));
}

MaterialToRender loadMaterial(const std::string& argument, std::vector<InputPath>& inputs) {
  const json material = loadMaterialArgument(argument);
  addMaterialInputs(inputs, argument, material);
  try {
    return {defaultLabel(argument, material), completeMaterial(material), makeRenderableMaterial(material)};
  } catch (const MaterialError& error) {
    if (isInlineMaterial(argument)) throw;
    throw MaterialError("material file " + inQuotes(argument) + ": " + error.what());
  }
}

struct LoadedEnvironment {
  std::optional<Environment> environment;  // none: a black background
  json description;
};

// --env, or the scene's own: white for the sphere and preview scenes, none for the caustic.
std::string environmentChoice(const RenderCommandOptions& options, ScenePreset preset) {
  if (!options.env.empty()) return options.env;
  return preset == ScenePreset::Caustic ? "none" : "white";
}

LoadedEnvironment loadEnvironment(const RenderCommandOptions& options, ScenePreset preset) {
  const Transform rotation = Transform::rotate(options.envRotateDegrees, Vec3d(0, 0, 1));
  const std::string env = environmentChoice(options, preset);
  if (env == "none") return {std::nullopt, {{"type", "none"}}};
  if (env == "white") return {Environment::constant(Rgb(options.envStrength)), {{"type", "constant"}}};
  try {
    EnvironmentMapFile file = readEnvironmentMap(options.env);
    const json description{{"type", "map"},
                           {"file", options.env},
                           {"size", {file.image.width(), file.image.height()}},
                           {"clamped_negative_values", file.clampedNegatives},
                           {"most_negative_value", file.mostNegative}};
    return {Environment::fromMap(std::move(file.image), options.envStrength, rotation), description};
  } catch (const RenderInputError& error) {
    throw InputError(std::string("--env: ") + error.what());
  }
}

// The scene's lighting from --env and the --light options, which only the preview and caustic
// scenes (the ones with an area light) take.
PresetLighting lightingOf(const RenderCommandOptions& options, ScenePreset preset,
                          std::optional<Environment> environment) {
  PresetLighting lighting = presetLighting(preset, std::move(environment));
  const bool lightOptions = !options.lightPosition.empty() || options.lightRadius > 0 ||
                            options.lightStrength > 0 || options.noLight;
  if (!lighting.light) {
    if (lightOptions)
      throw InputError(
          "--light-position, --light-radius, --light-strength, --no-light: the sphere scene has no area "
          "light; allowed: with --scene preview or caustic");
    return lighting;
  }
  if (options.noLight) {
    if (!options.lightPosition.empty() || options.lightRadius > 0 || options.lightStrength > 0)
      throw InputError(
          "--no-light: removes the light; allowed: without --light-position, --light-radius, "
          "--light-strength");
    lighting.light.reset();
    return lighting;
  }
  if (!options.lightPosition.empty())
    lighting.light->position =
        Vec3d(options.lightPosition[0], options.lightPosition[1], options.lightPosition[2]);
  if (options.lightRadius > 0) lighting.light->radius = options.lightRadius;
  if (options.lightStrength > 0) lighting.light->radiance *= options.lightStrength;
  // The light must not swallow the sphere or sit in the ground.
  const Sphere sphere = presetSphere();
  const PresetLight& light = *lighting.light;
  if (glm::length(light.position - sphere.center) < light.radius + sphere.radius ||
      light.position.z - light.radius <= -MaterialSphereSetup::SphereRadius)
    throw InputError("--light-position, --light-radius: a light of radius " + std::to_string(light.radius) +
                     " at (" + std::to_string(light.position.x) + ", " + std::to_string(light.position.y) +
                     ", " + std::to_string(light.position.z) +
                     ") meets the sphere or the ground; allowed: a light clear of the unit sphere at the "
                     "origin and above the ground z = -1");
  return lighting;
}

json lightJson(const PresetLighting& lighting) {
  if (!lighting.light) return nullptr;
  const PresetLight& l = *lighting.light;
  return {{"position", {l.position.x, l.position.y, l.position.z}},
          {"radius", l.radius},
          {"radiance", {l.radiance.x, l.radiance.y, l.radiance.z}}};
}

Estimator estimatorOf(const std::string& name) {
  if (name == "bsdf") return Estimator::BsdfOnly;
  if (name == "light") return Estimator::LightOnly;
  return Estimator::Mis;
}

struct OutputPaths {
  fs::path exr, png;
};

// PREFIX.exr and PREFIX.png, staged together (staged_outputs.h).
OutputPaths addOutputs(StagedOutputs& outputs, const std::string& prefix) {
  const std::string example = "out/gold (for out/gold.exr and out/gold.png)";
  if (prefix.empty()) throw InputError("--out: missing; allowed: a path prefix, e.g. " + example);
  if (prefix.back() == '/')
    throw InputError("--out: " + inQuotes(prefix) + " ends in '/'; allowed: a path prefix, e.g. " + example);
  // A device given as the prefix (/dev/null) is no place for two files beside it.
  std::error_code error;
  const fs::file_status status = fs::status(prefix, error);
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status))
    throw InputError("--out: " + inQuotes(prefix) +
                     " is a device, pipe or socket; allowed: a path prefix, e.g. " + example);
  OutputPaths paths{fs::path(prefix + ".exr"), fs::path(prefix + ".png")};
  outputs.addFile("--out", paths.exr, example);
  outputs.addFile("--out", paths.png, example);
  return paths;
}

// Memory of the images the run holds: each material's colour (and layers) until the end, and
// a gallery's sheet; 12 bytes per RGB float pixel, plus the PNG's 3.
double imageBytes(int64_t pixels, size_t materials, int layers, bool gallery) {
  const double perPixel = 12.0 * (1 + layers);
  return double(pixels) * (double(materials) * perPixel + (gallery ? 12.0 : 0.0) + 3.0);
}

// Why a region can be empty: silhouette_mask.h counts a pixel only 3 pixel widths inside
// (sphere) or outside (background) the silhouette, which a tiny image has none of.
constexpr const char* EmptyRegionNote =
    "no pixel lies 3 pixel widths inside it (pixels near the silhouette count for neither region)";

// An empty region has no mean: null, and why.
json statisticsJson(const RegionStatistics& s) {
  if (s.pixels == 0) return {{"n", 0}, {"mean", nullptr}, {"note", EmptyRegionNote}};
  return {{"n", s.pixels},
          {"mean_rgb", {s.meanRgb.x, s.meanRgb.y, s.meanRgb.z}},
          {"std_rgb", {s.stdRgb.x, s.stdRgb.y, s.stdRgb.z}},
          {"mean", s.mean},
          {"std", s.std},
          {"min", s.min},
          {"max", s.max}};
}

// A bar for the progress line: "[#####.....]".
std::string progressBar(double fraction) {
  constexpr int Width = 24;
  const int filled = std::clamp(int(fraction * Width + 0.5), 0, Width);
  return "[" + std::string(size_t(filled), '#') + std::string(size_t(Width - filled), '.') + "]";
}

// Writes both files into their temporaries, then puts both in place: a failed write leaves
// the previous pair as it was (staged_outputs.h).
void writeBoth(StagedOutputs& outputs, const OutputPaths& paths, const std::vector<ExrLayer>& layers,
               const Image& color, double exposure) {
  try {
    writeExr(outputs.staged(paths.exr), layers);
    writePngSrgb(outputs.staged(paths.png), color, exposure);
  } catch (const RenderInputError& error) {
    throw InputError(std::string("--out: ") + error.what());
  }
  outputs.commit();
}

// The run's wall time, from a pilot of each material: a small image with few samples per
// pixel, timed, scaled to the full image and sample count. Only for runs that could be long.
double estimateRenderSeconds(const ScenePreset preset, const std::vector<MaterialToRender>& materials,
                             SubsurfaceMode mode, const PresetLighting& lighting,
                             const Resolution& resolution, const RenderSettings& settings) {
  constexpr int PilotSide = 24, PilotSpp = 4;
  double seconds = 0.0;
  for (const MaterialToRender& material : materials) {
    const int width =
        std::max(1, PilotSide * resolution.width / std::max(resolution.width, resolution.height));
    const int height =
        std::max(1, PilotSide * resolution.height / std::max(resolution.width, resolution.height));
    const Scene pilot =
        makeMaterialScene(preset, makeRenderableMaterial(material.completed), mode, lighting, width, height);
    RenderSettings pilotSettings = settings;
    pilotSettings.samplesPerPixel = std::min(PilotSpp, settings.samplesPerPixel);
    const auto start = std::chrono::steady_clock::now();
    render(pilot, pilotSettings);
    const double pilotSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double scale = double(resolution.width) * resolution.height * settings.samplesPerPixel /
                         (double(width) * height * pilotSettings.samplesPerPixel);
    seconds += pilotSeconds * scale;
  }
  return seconds;
}

}  // namespace

std::optional<Resolution> parseResolution(const std::string& text) {
  const auto separator = text.find('x');
  const auto width = parsePositive(text.substr(0, separator));
  const auto height = separator == std::string::npos ? width : parsePositive(text.substr(separator + 1));
  if (!width || !height || *width > MaxImageSide || *height > MaxImageSide ||
      int64_t(*width) * int64_t(*height) > MaxImagePixels)
    return std::nullopt;
  return Resolution{*width, *height};
}

CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "render",
      "Path-trace material spheres: PREFIX.exr (linear float) and PREFIX.png (sRGB); two or more "
      "materials make a labelled contact sheet (gallery)");
  command
      ->add_option("material", options.materials,
                   "Material(s): inline JSON, JSON files, or measured files (MERL .binary, RGL .bsdf); "
                   "several: a gallery")
      ->required();
  command
      ->add_option("--integrator", options.integrator,
                   "Estimator: path (path tracing, NEE + MIS), light (light tracing: particles from the "
                   "lights to the eye), bdpt (bidirectional, every strategy under MIS) or sppm (stochastic "
                   "progressive photon mapping: --spp iterations); subsurface materials: path only")
      ->check(choiceOf(integratorNames(), "an integrator"))
      ->capture_default_str();
  command
      ->add_option("--scene", options.scene,
                   "Built-in scene: sphere (the peers' material sphere), preview (on a checkered ground, "
                   "with a small sphere light) or caustic (on a grey ground, lit by that light alone)")
      ->check(choiceOf(scenePresetNames(), "a scene"))
      ->capture_default_str();
  command
      ->add_option(
          "--env", options.env,
          "Environment: white (constant radiance 1, the furnace), none (black) or an equirectangular "
          "OpenEXR map (width = 2 x height; column u looks along phi = pi - 2 pi u, as Cycles); "
          "default: white, none for --scene caustic")
      ->type_name("FILE|white|none");
  const PresetLight light;
  command
      ->add_option("--light-position", options.lightPosition,
                   "Preview and caustic scenes: move the sphere light to X,Y,Z (default " +
                       std::to_string(light.position.x) + "," + std::to_string(light.position.y) + "," +
                       std::to_string(light.position.z) + ")")
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z")
      ->check(numberIn(ValueRange::closed(-1e3, 1e3), "a coordinate"));
  command
      ->add_option("--light-radius", options.lightRadius,
                   "Preview and caustic scenes: the sphere light's radius (default " +
                       std::to_string(light.radius) + ")")
      ->type_name("R")
      ->check(numberIn(ValueRange{1e-4, 1e3, false, false}, "a radius"));
  command
      ->add_option("--light-strength", options.lightStrength,
                   "Preview and caustic scenes: scale the sphere light's radiance (default radiance " +
                       std::to_string(light.radiance.x) + ")")
      ->type_name("S")
      ->check(numberIn(ValueRange{0.0, 1e6, true, false}, "a strength"));
  command->add_flag("--no-light", options.noLight, "Preview and caustic scenes: remove the sphere light");
  command->add_option("--env-strength", options.envStrength, "Environment radiance scale")
      ->type_name("S")
      ->check(numberIn(ValueRange::closed(0.0, 1e6)))
      ->capture_default_str();
  command
      ->add_option("--env-rotate", options.envRotateDegrees, "Turn the environment about +Z by DEG degrees")
      ->type_name("DEG")
      ->check(numberIn(ValueRange::closed(-360.0, 360.0), "degrees"))
      ->capture_default_str();
  command->add_option("--spp", options.spp, "Samples per pixel")
      ->type_name("N")
      ->transform(integerIn(1, MaxSamplesPerPixel))
      ->capture_default_str();
  command->add_option("--res", options.resolution, "Image size WxH (or N for N x N)")
      ->type_name("WxH")
      ->check(resolutionValidator())
      ->capture_default_str();
  command
      ->add_option("--threads", options.threads,
                   "Worker threads (0: all cores); the image does not depend on it")
      ->type_name("N")
      ->transform(integerIn(0, 1024))
      ->capture_default_str();
  command->add_option("--seed", options.seed, "Seed; the same seed gives the same image")
      ->type_name("N")
      ->transform(integerIn(0))
      ->capture_default_str();
  command->add_option("--max-depth", options.maxDepth, "Most bounces per path (Cycles' max_bounces)")
      ->type_name("N")
      ->transform(integerIn(0, MaxPathDepth))
      ->capture_default_str();
  command
      ->add_option("--estimator", options.estimator,
                   "The path tracer's direct light: mis (NEE + BSDF sampling, power heuristic; the default), "
                   "bsdf (BSDF sampling only) or light (light sampling only): for checking that they agree")
      ->check(choiceOf({"mis", "bsdf", "light"}, "an estimator"));
  command
      ->add_option(
          "--subsurface", options.subsurface,
          "How subsurface materials render: diffusion (the BSSRDF's profile, probe-ray exit points) or "
          "walk (brute-force volumetric random walk inside the sphere, the reference)")
      ->check(choiceOf(subsurfaceModeNames(), "a subsurface mode"))
      ->capture_default_str();
  command->add_option("--photons", options.photons, "SPPM: photons per iteration (default: one per pixel)")
      ->type_name("N")
      ->transform(integerIn(1, uint64_t(1) << 32));
  command
      ->add_option("--sppm-radius", options.sppmRadius,
                   "SPPM: the initial gather radius in pixel footprints at the scene's centre (default " +
                       std::to_string(SppmSettings{}.initialRadiusPixels) + ")")
      ->type_name("PIXELS")
      ->check(numberIn(ValueRange{1e-3, 1e3, false, false}, "a radius"));
  command
      ->add_option("--filter", options.filter,
                   "Pixel filter: box (1 pixel) or gaussian (sigma 0.5, radius 1.5 px)")
      ->check(choiceOf({"box", "gaussian"}, "a filter"))
      ->capture_default_str();
  command->add_option("--exposure", options.exposure, "PNG exposure in stops (x 2^EV before sRGB encoding)")
      ->type_name("EV")
      ->check(numberIn(ValueRange::closed(-30.0, 30.0), "stops"))
      ->capture_default_str();
  command
      ->add_option("--layers", options.layers,
                   "Extra EXR layers: albedo, normal, variance (single material only; sppm has no variance)")
      ->delimiter(',')
      ->check(choiceOf({"albedo", "normal", "variance"}, "a layer"));
  command->add_option("--label", options.labels,
                      "Gallery label per material, in order (default: file name or type)");
  command->add_option("--columns", options.columns, "Gallery columns (0: a square-ish grid)")
      ->type_name("N")
      ->transform(integerIn(0, 1024))
      ->capture_default_str();
  command->add_option("--out", options.out, "Output prefix: writes PREFIX.exr and PREFIX.png")
      ->type_name("PREFIX")
      ->required();
  command->add_flag("--json", options.json,
                    "Print the run (settings, timings, sphere and background means) as JSON");
  addPluginOption(*command);
  return command;
}

namespace {

// Every input of a run, validated (all but --out), ready to render.
struct RenderPlan {
  Resolution resolution;
  ScenePreset preset;
  IntegratorKind integrator;
  bool gallery = false;
  int64_t pixels = 0;
  std::vector<InputPath> inputs;
  std::vector<MaterialToRender> materials;
  json environment;  // its description
  PresetLighting lighting;
  SubsurfaceMode subsurfaceMode;
  RenderSettings settings;
};

// Every input first: nothing is rendered or written unless all of it is valid.
RenderPlan planRender(const RenderCommandOptions& options) {
  RenderPlan plan;
  const auto resolution = parseResolution(options.resolution);
  if (!resolution)
    throw InputError("--res: " + inQuotes(options.resolution) +
                     " is not valid; allowed: " + ResolutionAllowed);
  plan.resolution = *resolution;
  plan.preset = *findScenePreset(options.scene);
  plan.integrator = *findIntegrator(options.integrator);
  const IntegratorKind integrator = plan.integrator;
  if (integrator != IntegratorKind::Path && !options.estimator.empty())
    throw InputError("--estimator: chooses the path tracer's direct light; allowed: with --integrator path");
  if (integrator != IntegratorKind::Sppm && (options.photons > 0 || options.sppmRadius > 0))
    throw InputError("--photons, --sppm-radius: photon mapping's settings; allowed: with --integrator sppm");
  if (integrator == IntegratorKind::Sppm &&
      std::find(options.layers.begin(), options.layers.end(), "variance") != options.layers.end())
    throw InputError(
        "--layers: \"variance\": sppm has no variance layer (it is consistent, not unbiased: its "
        "error is no sample variance); allowed: albedo, normal");
  plan.gallery = options.materials.size() > 1;
  if (!options.labels.empty() && options.labels.size() != options.materials.size())
    throw InputError("--label: " + std::to_string(options.labels.size()) + " labels for " +
                     std::to_string(options.materials.size()) +
                     " materials; allowed: one label per material");
  if (plan.gallery && !options.layers.empty())
    throw InputError("--layers: only with a single material; a gallery writes the colour sheet alone");
  // A gallery renders every sphere at --res: all of them count against the pixel limit.
  plan.pixels = int64_t(resolution->width) * resolution->height;
  if (plan.pixels * int64_t(options.materials.size()) > MaxImagePixels)
    throw InputError("--res: " + std::to_string(options.materials.size()) + " materials x " +
                     std::to_string(resolution->width) + "x" + std::to_string(resolution->height) + " = " +
                     std::to_string(plan.pixels * int64_t(options.materials.size())) +
                     " pixels; allowed: at most " + std::to_string(MaxImagePixels) +
                     " pixels in all (a gallery renders each material at --res)");
  for (size_t i = 0; i < options.materials.size(); ++i) {
    plan.materials.push_back(loadMaterial(options.materials[i], plan.inputs));
    if (!options.labels.empty()) plan.materials.back().label = options.labels[i];
    if (integrator != IntegratorKind::Path && plan.materials.back().material.subsurface)
      throw InputError("material " + inQuotes(options.materials[i]) +
                       ": a subsurface material (a BSSRDF), which --integrator " + options.integrator +
                       " does not render; allowed: --integrator path, or a BSDF");
  }
  if (const std::string env = environmentChoice(options, plan.preset); env != "white" && env != "none")
    plan.inputs.push_back({"environment map (--env)", env});
  LoadedEnvironment loaded = loadEnvironment(options, plan.preset);
  plan.environment = loaded.description;
  plan.lighting = lightingOf(options, plan.preset, std::move(loaded.environment));
  plan.subsurfaceMode = *findSubsurfaceMode(options.subsurface);

  RenderSettings& settings = plan.settings;
  settings.integratorKind = integrator;
  if (options.photons > 0) settings.sppm.photonsPerIteration = options.photons;
  if (options.sppmRadius > 0) settings.sppm.initialRadiusPixels = options.sppmRadius;
  settings.samplesPerPixel = options.spp;
  settings.seed = options.seed;
  settings.threads = options.threads;
  settings.filter = options.filter == "gaussian" ? PixelFilter::gaussian() : PixelFilter::box();
  settings.integrator.maxDepth = options.maxDepth;
  settings.integrator.estimator = estimatorOf(options.estimator);
  for (const std::string& layer : options.layers) {
    settings.albedoLayer |= layer == "albedo";
    settings.normalLayer |= layer == "normal";
    settings.varianceLayer |= layer == "variance";
  }
  return plan;
}

struct RenderRuns {
  json runs = json::array();
  // Samples the film dropped (not finite, or negative: render.h); any fails the command.
  uint64_t droppedSamples = 0;
  std::string droppedMessages;  // printed once the progress line is gone
  std::vector<RenderResult> results;
};

// Renders every material of the plan (consuming them) in order.
RenderRuns renderMaterials(RenderPlan& plan, bool showProgress) {
  RenderRuns out;
  const Resolution& resolution = plan.resolution;
  ProgressLine progress;
  for (size_t i = 0; i < plan.materials.size(); ++i) {
    MaterialToRender& material = plan.materials[i];
    const Scene scene = makeMaterialScene(plan.preset, std::move(material.material), plan.subsurfaceMode,
                                          plan.lighting, resolution.width, resolution.height);
    const std::string step =
        plan.gallery ? "[" + std::to_string(i + 1) + "/" + std::to_string(plan.materials.size()) + "] " : "";
    const ProgressCallback report =
        showProgress ? progress.callback("render " + step + material.label) : ProgressCallback();
    RenderResult result = render(scene, plan.settings, [&](double fraction) {
      if (report) report(progressBar(fraction), fraction);
    });
    const RenderStatistics& stats = result.statistics;
    json run{{"label", material.label},
             {"material", material.completed},
             {"seconds", stats.seconds},
             {"samples", stats.samples},
             {"vertices", stats.vertices},
             {"samples_per_second", double(stats.samples) / stats.seconds},
             {"vertices_per_second", double(stats.vertices) / stats.seconds},
             {"non_finite_samples", stats.nonFiniteSamples},
             {"negative_samples", stats.negativeSamples},
             {"dropped_samples", stats.droppedSamples()}};
    out.droppedSamples += stats.droppedSamples();
    out.droppedMessages += droppedSampleMessage(material.label, stats);
    if (plan.preset == ScenePreset::MaterialSphere) {
      const SilhouetteMask mask = silhouetteMask(scene.camera(), presetSphere());
      run["sphere"] = statisticsJson(regionStatistics(result.color, mask, PixelRegion::Sphere));
      run["background"] = statisticsJson(regionStatistics(result.color, mask, PixelRegion::Background));
    }
    out.runs.push_back(std::move(run));
    out.results.push_back(std::move(result));
  }
  return out;
}

// What --json prints; `paths` null for a run that writes nothing.
json runJson(const RenderCommandOptions& options, const RenderPlan& plan, const RenderRuns& runs,
             const OutputPaths* paths) {
  return {{"integrator", options.integrator},
          {"scene", options.scene},
          {"env", environmentChoice(options, plan.preset)},
          {"environment", plan.environment},
          {"light", lightJson(plan.lighting)},
          {"env_strength", options.envStrength},
          {"env_rotate_degrees", options.envRotateDegrees},
          {"res", {plan.resolution.width, plan.resolution.height}},
          {"spp", options.spp},
          {"threads", options.threads},
          {"seed", options.seed},
          {"max_depth", options.maxDepth},
          {"estimator", plan.integrator == IntegratorKind::Path
                            ? json(options.estimator.empty() ? "mis" : options.estimator)
                            : json(nullptr)},
          {"subsurface", options.subsurface},
          {"filter", options.filter},
          {"exr", paths ? json(paths->exr.string()) : json(nullptr)},
          {"png", paths ? json(paths->png.string()) : json(nullptr)},
          {"renders", runs.runs},
          {"dropped_samples", runs.droppedSamples},
          {"passed", runs.droppedSamples == 0}};
}

void printRuns(const RenderCommandOptions& options, const RenderPlan& plan, const RenderRuns& runs,
               const OutputPaths& paths) {
  const Resolution& resolution = plan.resolution;
  for (const json& run : runs.runs) {
    std::cout << run["label"].get<std::string>() << ": " << resolution.width << "x" << resolution.height
              << ", " << options.spp << (plan.integrator == IntegratorKind::Sppm ? " iterations, " : " spp, ")
              << options.integrator << ", " << run["seconds"].get<double>() << " s, "
              << run["vertices_per_second"].get<double>() / 1e6 << " M path vertices/s";
    for (const char* region : {"sphere", "background"}) {
      if (!run.contains(region)) continue;
      if (run[region]["n"].get<size_t>() == 0)
        std::cout << ", " << region << " mean undefined at " << resolution.width << "x" << resolution.height
                  << " (" << EmptyRegionNote << ")";
      else
        std::cout << ", " << region << " mean " << run[region]["mean"].get<double>();
    }
    if (const uint64_t dropped = run["dropped_samples"].get<uint64_t>(); dropped > 0)
      std::cout << ", FAILED: " << dropped << " samples dropped ("
                << run["non_finite_samples"].get<uint64_t>() << " not finite, "
                << run["negative_samples"].get<uint64_t>() << " negative)";
    std::cout << "\n";
  }
  std::cout << "wrote " << paths.exr.string() << " and " << paths.png.string() << "\n";
}

}  // namespace

RenderReport renderReport(const RenderCommandOptions& options, bool progress) {
  if (options.materials.size() != 1)
    throw InputError("material: " + std::to_string(options.materials.size()) +
                     " given; allowed: one material (a gallery is the command line's)");
  RenderPlan plan = planRender(options);
  RenderRuns runs = renderMaterials(plan, progress);
  std::cerr << runs.droppedMessages;
  RenderReport report{runJson(options, plan, runs, nullptr), std::move(runs.results.front())};
  return report;
}

int runRenderCommand(const RenderCommandOptions& options) {
  RenderPlan plan = planRender(options);
  StagedOutputs outputs(plan.inputs);
  const OutputPaths paths = addOutputs(outputs, options.out);

  // ---- Claim the outputs (nothing is written before this point: an unwritable one is bad
  // input now, not after the work), then announce long work.
  outputs.prepare();
  const double totalSamples = double(plan.pixels) * double(options.spp) * double(plan.materials.size());
  constexpr double PilotAboveSamples = 5e7;  // ~10 s at a few million samples per second
  if (totalSamples > PilotAboveSamples)
    announceWork({"render: " + std::to_string(plan.materials.size()) + " x " +
                      std::to_string(plan.resolution.width) + "x" + std::to_string(plan.resolution.height) +
                      " px x " + std::to_string(options.spp) + " spp",
                  estimateRenderSeconds(plan.preset, plan.materials, plan.subsurfaceMode, plan.lighting,
                                        plan.resolution, plan.settings),
                  imageBytes(plan.pixels, plan.materials.size(), int(options.layers.size()), plan.gallery)});

  // ---- Render.
  const RenderRuns runs = renderMaterials(plan, true);
  std::cerr << runs.droppedMessages;

  // ---- Write.
  const std::vector<RenderResult>& results = runs.results;
  if (plan.gallery) {
    std::vector<ContactSheetEntry> entries;
    for (size_t i = 0; i < results.size(); ++i)
      entries.push_back({&results[i].color, plan.materials[i].label});
    ContactSheetLayout layout;
    layout.columns = options.columns;
    const Image sheet = composeContactSheet(entries, layout);
    writeBoth(outputs, paths, {{"", {"R", "G", "B"}, &sheet}}, sheet, options.exposure);
  } else {
    const RenderResult& result = results.front();
    std::vector<ExrLayer> layers{{"", {"R", "G", "B"}, &result.color}};
    if (plan.settings.albedoLayer) layers.push_back({"albedo", {"R", "G", "B"}, &result.albedo});
    if (plan.settings.normalLayer) layers.push_back({"normal", {"X", "Y", "Z"}, &result.normal});
    if (plan.settings.varianceLayer) layers.push_back({"variance", {"R", "G", "B"}, &result.variance});
    writeBoth(outputs, paths, layers, result.color, options.exposure);
  }

  if (options.json)
    std::cout << runJson(options, plan, runs, &paths).dump(2, ' ', false, json::error_handler_t::replace)
              << "\n";
  else
    printRuns(options, plan, runs, paths);
  return droppedSampleStatus(runs.droppedSamples);
}

}  // namespace scatterlab
