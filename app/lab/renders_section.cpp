#include "app/lab/renders_section.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "app/data_directory.h"
#include "app/exit_code.h"
#include "app/lab/html.h"
#include "integrator/environment_map_file.h"
#include "integrator/exr_io.h"
#include "integrator/material_scene.h"
#include "integrator/png_io.h"
#include "integrator/render.h"
#include "integrator/render_error.h"
#include "integrator/silhouette_mask.h"
#include "materials/core/atomic_file.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The difference images are shown this many times brighter than the renders (2 stops), so
// that a difference of a few percent of the sphere is visible.
constexpr double DifferenceGain = 4.0;
// The renders of one environment are exposed so that the material's whole image has this mean
// (a mid grey), clamped to +- MaxExposureStops.
constexpr double MidGrey = 0.18;
constexpr double MaxExposureStops = 12.0;

// One description to render: the material itself or a fit.
struct Subject {
  std::string label;  // "gold-metallic-paint", "Lambert + GGX"
  std::string key;    // file-name part: "material", "fit1"
  std::optional<json> material;
  std::string problem;  // why there is no description (a fit that could not be written)
};

double channelMean(const Rgb& c) { return (c.x + c.y + c.z) / 3.0; }

double imageMean(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += channelMean(image.rgb(x, y));
  return sum / double(std::max(1, image.width() * image.height()));
}

double exposureFor(const Image& reference) {
  const double mean = imageMean(reference);
  return mean > 0 ? std::clamp(std::log2(MidGrey / mean), -MaxExposureStops, MaxExposureStops) : 0.0;
}

json rgbJson(const Rgb& c) { return json{c.x, c.y, c.z}; }

// The numbers of a difference over the sphere's pixels (silhouette_mask.h), relative to the
// material's mean there: mean |a - b|, the root mean square of a - b, and the noise level, the
// root mean square that a - b would have from the two renders' noise alone (their pixel-mean
// variances added; an upper bound, since common random numbers correlate the two).
struct DifferenceNumbers {
  double meanAbs = 0, rms = 0, noise = 0;
};

DifferenceNumbers differenceOver(const Image& a, const Image& b, const Image& varianceA,
                                 const Image& varianceB, const SilhouetteMask& mask, Image& difference) {
  double sumA = 0, sumAbs = 0, sumSquared = 0, sumVariance = 0;
  size_t n = 0;
  difference = Image(a.width(), a.height());
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgb d = a.rgb(x, y) - b.rgb(x, y);
      difference.setRgb(x, y, d);
      if (mask.at(x, y) != PixelRegion::Sphere) continue;
      ++n;
      sumA += channelMean(a.rgb(x, y));
      sumAbs += channelMean(glm::abs(d));
      sumSquared += channelMean(d * d);
      sumVariance += channelMean(varianceA.rgb(x, y) + varianceB.rgb(x, y));
    }
  if (n == 0 || !(sumA > 0)) return {};
  const double mean = sumA / double(n);
  return {sumAbs / sumA, std::sqrt(sumSquared / double(n)) / mean, std::sqrt(sumVariance / double(n)) / mean};
}

Image absolute(const Image& image) {
  Image out = image;
  for (float& v : out.data()) v = std::abs(v);
  return out;
}

std::string percent(double fraction) { return html::number(100.0 * fraction, 3) + "%"; }

std::string figure(const std::string& src, const std::string& alt, const std::string& caption) {
  return html::element(
      "figure", html::voidElement("img", {{"src", src}, {"alt", alt}}) + html::element("figcaption", caption),
      {{"class", "render"}});
}

std::string refusalBox(const std::string& label, const std::string& message) {
  return html::element("div",
                       html::textElement("b", "Not rendered: " + label) + html::element("br", "") +
                           html::textElement("span", "The renderer's message: ") +
                           html::textElement("code", message),
                       {{"class", "render-refused"}});
}

// The red box of samples the film dropped (render.h): what rendered and how many.
std::string droppedBox(const std::string& lines) {
  return html::element("div",
                       html::textElement("b", "Samples dropped: the renders below are missing light") +
                           html::element("br", "") +
                           html::textElement("span",
                                             "Samples whose value was not finite or negative count as 0 "
                                             "in the image (no light transport produces one): ") +
                           html::element("ul", lines),
                       {{"class", "failures"}});
}

// A render and its sphere's statistics.
struct Rendered {
  RenderResult result;
  RegionStatistics sphere;
};

// The files of subject `key` under environment `env`: STEM.png and STEM.exr.
std::string renderStem(const std::string& env, const std::string& key) { return "render_" + env + "_" + key; }
std::string differenceStem(const std::string& env, const std::string& key) {
  return "difference_" + env + "_" + key;
}

std::vector<Subject> subjectsOf(const LabMaterial& material, const MaterialFits* fits) {
  std::vector<Subject> subjects{{material.name, "material", material.description, ""}};
  if (fits)
    for (size_t i = 0; i < fits->families.size(); ++i) {
      const FamilyFit& f = fits->families[i];
      subjects.push_back({f.name, "fit" + std::to_string(i + 1), f.written.material, f.written.problem});
    }
  return subjects;
}

}  // namespace

std::vector<std::string> defaultLabEnvironmentFiles() {
  const fs::path maps =
      runtimeDataDirectory("the lab's default environment maps (or give --env)") / "envmaps";
  return {(maps / "studio.exr").string(), (maps / "courtyard.exr").string()};
}

std::vector<LabEnvironment> loadLabEnvironments(const std::vector<std::string>& files) {
  std::vector<LabEnvironment> environments;
  for (const std::string& file : files) {
    try {
      EnvironmentMapFile map = readEnvironmentMap(file);
      json description{{"file", file},
                       {"size", {map.image.width(), map.image.height()}},
                       {"clamped_negative_values", map.clampedNegatives}};
      std::string name = fs::path(file).stem().string();
      for (const LabEnvironment& other : environments)
        if (other.name == name)
          name += "-" + std::to_string(environments.size() + 1);  // file names stay apart
      environments.push_back(
          {name, file, Environment::fromMap(std::move(map.image)), std::move(description)});
    } catch (const RenderInputError& error) {
      throw InputError(std::string("--env: ") + error.what());
    }
  }
  return environments;
}

SphereSceneFactory integratorSphereScene() {
  return [](const json& material, const Environment& environment, int size) {
    return makeMaterialScene(ScenePreset::MaterialSphere, material, environment, size, size);
  };
}

PreviewSceneFactory integratorPreviewScene() {
  return [](const json& material, const Environment& environment, int width, int height) {
    return makeMaterialScene(ScenePreset::Preview, material, environment, width, height);
  };
}

namespace {

// The material on the preview scene under the first map: preview.png and preview.exr, and its
// entry for renders.json; an empty html when the renderer refused the material. Its dropped
// samples join the sphere renders' in the section's count and red box (render.h).
struct PreviewRender {
  std::string html;
  json data;
  RenderStatistics statistics;
};

PreviewRender previewRender(const LabMaterial& material, const LabSettings& settings,
                            const LabEnvironment& environment, const fs::path& materialDir,
                            const ProgressCallback& progress, const PreviewSceneFactory& previewOf) {
  const Scene scene =
      previewOf(material.description, environment.environment, settings.previewWidth, settings.previewHeight);
  RenderSettings renderSettings;
  renderSettings.samplesPerPixel = settings.previewSpp;
  renderSettings.seed = settings.seed;
  renderSettings.integrator.maxDepth = settings.renderMaxDepth;
  const std::string stage = "render " + material.name + " on the preview scene";
  const RenderResult result = render(scene, renderSettings, [&](double fraction) {
    if (progress) progress(stage, fraction);
  });
  const double exposure = exposureFor(result.color);
  writePngSrgb(materialDir / "preview.png", result.color, exposure);
  writeExr(materialDir / "preview.exr", {{"", {"R", "G", "B"}, &result.color}});
  const std::string caption = "on the preview scene (checkered ground, sphere light) under " +
                              environment.name + ", " + std::to_string(settings.previewWidth) + " x " +
                              std::to_string(settings.previewHeight) + " pixels, " +
                              std::to_string(settings.previewSpp) + " samples per pixel, exposure " +
                              html::number(exposure, 3) + " stops";
  return {figure(material.folder + "/preview.png", material.name + " on the preview scene",
                 html::textElement("b", material.name) + html::element("br", "") + html::escape(caption)),
          {{"image", "preview.png"},
           {"exr", "preview.exr"},
           {"environment", environment.name},
           {"size", {settings.previewWidth, settings.previewHeight}},
           {"samples_per_pixel", settings.previewSpp},
           {"exposure_stops", exposure},
           {"seconds", result.statistics.seconds},
           {"samples", result.statistics.samples},
           {"non_finite_samples", result.statistics.nonFiniteSamples},
           {"negative_samples", result.statistics.negativeSamples},
           {"dropped_samples", result.statistics.droppedSamples()}},
          result.statistics};
}

// One line of the red box (droppedBox): what was rendered and how many of its samples were dropped.
std::string droppedLine(const std::string& what, const RenderStatistics& statistics) {
  return html::textElement("li", what + ": " + std::to_string(statistics.droppedSamples()) + " of " +
                                     std::to_string(statistics.samples) + " samples (" +
                                     std::to_string(statistics.nonFiniteSamples) + " not finite, " +
                                     std::to_string(statistics.negativeSamples) + " negative)");
}

}  // namespace

ReportSection rendersSection(const LabMaterial& material, const MaterialFits* fits,
                             const LabSettings& settings, const std::vector<LabEnvironment>& environments,
                             const fs::path& materialDir, const ProgressCallback& progress,
                             const SphereSceneFactory& sceneOf, const PreviewSceneFactory& previewOf) {
  ReportSection section;
  section.id = "renders";
  section.title = "Renders";
  RenderSettings renderSettings;
  renderSettings.samplesPerPixel = settings.renderSpp;
  renderSettings.seed = settings.seed;
  renderSettings.integrator.maxDepth = settings.renderMaxDepth;
  renderSettings.varianceLayer = true;
  const int size = settings.renderSize;

  const std::vector<Subject> subjects = subjectsOf(material, fits);
  // results[s][e]: subject s under environment e; empty when the renderer refused s.
  std::vector<std::vector<Rendered>> results(subjects.size());
  json refused = json::array(), renders = json::array();
  std::string refusals, droppedLines;
  uint64_t droppedSamples = 0;
  std::optional<SilhouetteMask> mask;
  for (size_t s = 0; s < subjects.size(); ++s) {
    const Subject& subject = subjects[s];
    std::optional<Scene> scene;
    std::string message = subject.problem;
    if (subject.material && !environments.empty()) {
      try {
        scene = sceneOf(*subject.material, environments.front().environment, size);
      } catch (const MaterialError& error) {
        message = error.what();
      } catch (const RenderInputError& error) {
        message = error.what();
      }
    }
    if (!scene) {
      refused.push_back({{"label", subject.label}, {"subject", subject.key}, {"message", message}});
      refusals += refusalBox(subject.label, message);
      continue;
    }
    if (!mask) mask = silhouetteMask(scene->camera(), presetSphere());
    for (size_t e = 0; e < environments.size(); ++e) {
      if (e > 0) scene->setEnvironment(environments[e].environment);
      const std::string stage = "render " + subject.label + " under " + environments[e].name;
      RenderResult result = render(*scene, renderSettings, [&](double fraction) {
        if (progress) progress(stage, fraction);
      });
      const RegionStatistics sphere = regionStatistics(result.color, *mask, PixelRegion::Sphere);
      const std::string stem = renderStem(environments[e].name, subject.key);
      renders.push_back({{"label", subject.label},
                         {"subject", subject.key},
                         {"environment", environments[e].name},
                         {"image", stem + ".png"},
                         {"exr", stem + ".exr"},
                         {"sphere_mean_rgb", rgbJson(sphere.meanRgb)},
                         {"sphere_pixels", sphere.pixels},
                         {"seconds", result.statistics.seconds},
                         {"samples", result.statistics.samples},
                         {"non_finite_samples", result.statistics.nonFiniteSamples},
                         {"negative_samples", result.statistics.negativeSamples},
                         {"dropped_samples", result.statistics.droppedSamples()}});
      if (const uint64_t dropped = result.statistics.droppedSamples(); dropped > 0) {
        droppedSamples += dropped;
        droppedLines += droppedLine(subject.label + " under " + environments[e].name, result.statistics);
      }
      results[s].push_back({std::move(result), sphere});
    }
  }

  // Write and show, environment by environment: the material, then each fit and its difference.
  json differences = json::array(), environmentsJson = json::array();
  std::string body;
  const std::string base = material.folder + "/";
  for (size_t e = 0; e < environments.size(); ++e) {
    const std::string& env = environments[e].name;
    const RenderResult* reference = results.front().empty() ? nullptr : &results.front()[e].result;
    const RenderResult* exposed = reference;
    for (size_t s = 0; !exposed && s < results.size(); ++s)
      if (!results[s].empty()) exposed = &results[s][e].result;
    if (!exposed) break;
    const double exposure = exposureFor(exposed->color);
    json environmentJson = environments[e].description;
    environmentJson["name"] = env;
    environmentJson["exposure_stops"] = exposure;
    environmentsJson.push_back(environmentJson);
    std::string figures;
    for (size_t s = 0; s < subjects.size(); ++s) {
      if (results[s].empty()) continue;
      const RenderResult& result = results[s][e].result;
      const std::string name = renderStem(env, subjects[s].key);
      writePngSrgb(materialDir / (name + ".png"), result.color, exposure);
      writeExr(materialDir / (name + ".exr"),
               {{"", {"R", "G", "B"}, &result.color}, {"variance", {"R", "G", "B"}, &result.variance}});
      figures += figure(base + name + ".png", subjects[s].label + " under " + env,
                        html::textElement("b", s == 0 ? subjects[s].label : "fit: " + subjects[s].label) +
                            html::element("br", "") +
                            html::escape("sphere mean " + html::rgb(results[s][e].sphere.meanRgb)));
      if (s == 0 || !reference) continue;
      Image difference;
      const DifferenceNumbers numbers = differenceOver(reference->color, result.color, reference->variance,
                                                       result.variance, *mask, difference);
      const std::string diffName = differenceStem(env, subjects[s].key);
      writePngSrgb(materialDir / (diffName + ".png"), absolute(difference),
                   exposure + std::log2(DifferenceGain));
      writeExr(materialDir / (diffName + ".exr"), {{"", {"R", "G", "B"}, &difference}});
      differences.push_back({{"environment", env},
                             {"fit", subjects[s].label},
                             {"subject", subjects[s].key},
                             {"image", diffName + ".png"},
                             {"exr", diffName + ".exr"},
                             {"gain", DifferenceGain},
                             {"relative_mean_abs_difference", numbers.meanAbs},
                             {"relative_rms_difference", numbers.rms},
                             {"relative_rms_noise", numbers.noise}});
      figures += figure(base + diffName + ".png", "difference of " + subjects[s].label + " under " + env,
                        html::escape("|" + material.name + " - fit| x " + html::number(DifferenceGain, 2)) +
                            html::element("br", "") +
                            html::escape("mean " + percent(numbers.meanAbs) + ", rms " +
                                         percent(numbers.rms) + " (noise " + percent(numbers.noise) + ")"));
    }
    body += html::textElement("h4", "under " + env + " (" + environments[e].file + "), exposure " +
                                        html::number(exposure, 3) + " stops") +
            html::element("div", figures, {{"class", "renders"}});
  }

  const std::string about = html::textElement(
      "p",
      "The sphere path-traced under each environment map, " + std::to_string(size) + " x " +
          std::to_string(size) + " pixels, " + std::to_string(settings.renderSpp) +
          " samples per pixel, at most " + std::to_string(settings.renderMaxDepth) +
          " bounces, every render of a map with the same random numbers." +
          (fits ? " Each fit beside the material with |material - fit| (the sphere's mean absolute and rms "
                  "difference relative to its mean, next to the rms the renders' noise alone would give). "
                : " ") +
          "Linear EXR images (with the variance of each pixel's mean) and renders.json are beside the PNGs.",
      {{"class", "small"}});
  // The material alone on the preview scene, when the renderer took it.
  json preview = nullptr;
  if (!results.front().empty()) {
    PreviewRender p =
        previewRender(material, settings, environments.front(), materialDir, progress, previewOf);
    body += html::textElement("h4", "on the preview scene") +
            html::element("div", p.html, {{"class", "renders"}});
    if (const uint64_t dropped = p.statistics.droppedSamples(); dropped > 0) {
      droppedSamples += dropped;
      droppedLines += droppedLine(material.name + " on the preview scene", p.statistics);
    }
    preview = std::move(p.data);
  }

  section.html = (droppedLines.empty() ? "" : droppedBox(droppedLines)) + refusals + about + body;
  section.data = {{"size", {size, size}},
                  {"samples_per_pixel", settings.renderSpp},
                  {"max_depth", settings.renderMaxDepth},
                  {"seed", settings.seed},
                  {"environments", environmentsJson},
                  {"renders", renders},
                  {"differences", differences},
                  {"refused", refused},
                  {"dropped_samples", droppedSamples},
                  {"preview", preview}};
  writeTextFileAtomically(materialDir / "renders.json", section.data.dump(1) + "\n");
  return section;
}

namespace {

// The differences, listed map by map in the data, gathered per fit in order.
std::vector<std::pair<std::string, std::vector<const json*>>> differencesByFit(const ReportSection& renders) {
  std::vector<std::pair<std::string, std::vector<const json*>>> fits;
  if (!renders.data.contains("differences")) return fits;
  for (const json& d : renders.data.at("differences")) {
    const std::string fit = d.value("fit", "");
    auto it = std::find_if(fits.begin(), fits.end(), [&](const auto& f) { return f.first == fit; });
    if (it == fits.end()) it = fits.insert(fits.end(), {fit, {}});
    it->second.push_back(&d);
  }
  return fits;
}

std::string differencesText(const std::vector<const json*>& ds) {
  std::string text;
  for (size_t i = 0; i < ds.size(); ++i)
    text += (i ? ", " : "") + percent((*ds[i])["relative_mean_abs_difference"].get<double>()) + " (" +
            (*ds[i])["environment"].get<std::string>() + ")";
  return text;
}

}  // namespace

std::string closestFitInRenders(const ReportSection& renders) {
  const auto fits = differencesByFit(renders);
  const auto meanOf = [](const std::vector<const json*>& ds) {
    double sum = 0;
    for (const json* d : ds) sum += (*d)["relative_mean_abs_difference"].get<double>();
    return sum / double(ds.size());
  };
  const auto best = std::min_element(fits.begin(), fits.end(), [&](const auto& a, const auto& b) {
    return meanOf(a.second) < meanOf(b.second);
  });
  if (best == fits.end()) return "";
  return best->first + ": " + differencesText(best->second);
}

std::map<std::string, std::string> fitRenderDifferences(const ReportSection& renders) {
  std::map<std::string, std::string> out;
  for (const auto& [fit, ds] : differencesByFit(renders)) out[fit] = differencesText(ds);
  return out;
}

std::string renderRefusal(const ReportSection& renders) {
  for (const json& r : renders.data.value("refused", json::array()))
    if (r.value("subject", "") == "material") return r.value("message", "");
  return "";
}

}  // namespace scatterlab
