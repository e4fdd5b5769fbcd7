// The lab report's renders (app/lab/renders_section.h): the renderer decides what is rendered
// (a refusal is shown with its message, and a description of any type the renderer accepts is
// rendered), and the difference of a fit is the difference of the two renders.
//
// Every scene here is lit by a white furnace (constant radiance 1): a convex Lambertian sphere
// of albedo a then reflects exactly a toward the camera with zero variance (cosine-weighted
// BSDF sampling gives every path the weight a, and every scattered ray escapes to the
// environment), so the expected images and differences are exact numbers.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/lab/renders_section.h"
#include "integrator/material_scene.h"
#include "materials/registry/spec_validation.h"

#include "cli_runner.h"
#include "tests/validation/test_models.h"

namespace scatterlab {
namespace lab_renders_test {

namespace fs = std::filesystem;
using nlohmann::json;

LabSettings tinyRenders() {
  LabSettings settings = LabSettings::quickMode(7);
  settings.renderSize = 24;
  settings.renderSpp = 4;
  settings.previewWidth = 16;
  settings.previewHeight = 12;
  settings.previewSpp = 2;
  return settings;
}

std::vector<LabEnvironment> furnace() {
  std::vector<LabEnvironment> environments;
  environments.push_back({"furnace", "(constant 1)", Environment::constant(Rgb(1.0)), json::object()});
  return environments;
}

LabMaterial lambertian(double albedo) {
  LabMaterial m =
      describedLabMaterial("grey", {{"type", "lambertian"}, {"albedo", {albedo, albedo, albedo}}});
  m.folder = "grey";
  return m;
}

fs::path freshDir(const std::string& stem) {
  const fs::path dir = cli_runner::uniquePath(stem);
  fs::create_directories(dir);
  return dir;
}

// The integrator's own sphere, for any description, as a Lambertian of albedo 0.5: a renderer
// that can render everything.
Scene acceptEverything(const json&, const Environment& environment, int size) {
  return makeMaterialScene(ScenePreset::MaterialSphere,
                           json{{"type", "lambertian"}, {"albedo", {0.5, 0.5, 0.5}}}, environment, size,
                           size);
}

TEST(LabRenders, AMaterialTheRendererRefusesShowsTheRenderersMessage) {
  const fs::path dir = freshDir("lab-renders-refused");
  const SphereSceneFactory refuse = [](const json&, const Environment&, int) -> Scene {
    throw MaterialError("this renderer renders nothing (test)");
  };
  const ReportSection section =
      rendersSection(lambertian(0.5), nullptr, tinyRenders(), furnace(), dir, {}, refuse);
  EXPECT_EQ(renderRefusal(section), "this renderer renders nothing (test)");
  ASSERT_EQ(section.data["refused"].size(), 1u);
  EXPECT_TRUE(section.data["renders"].empty());
  cli_runner::expectMentions(section.html, {"class=\"render-refused\"", "Not rendered: grey",
                                            "this renderer renders nothing (test)"});
  EXPECT_FALSE(fs::exists(dir / "render_furnace_material.png"));
  EXPECT_TRUE(fs::exists(dir / "renders.json"));
  EXPECT_TRUE(section.data["preview"].is_null());
  EXPECT_FALSE(fs::exists(dir / "preview.png"));
}

// The material alone on the preview scene (ground, sphere light) under the first map.
TEST(LabRenders, TheMaterialIsShownOnThePreviewScene) {
  const fs::path dir = freshDir("lab-renders-preview");
  const LabSettings settings = tinyRenders();
  const ReportSection section = rendersSection(lambertian(0.5), nullptr, settings, furnace(), dir, {});
  const json& preview = section.data["preview"];
  ASSERT_TRUE(preview.is_object());
  EXPECT_EQ(preview["image"], "preview.png");
  EXPECT_EQ(preview["size"], json({settings.previewWidth, settings.previewHeight}));
  EXPECT_EQ(
      preview["samples"].get<uint64_t>(),
      uint64_t(settings.previewWidth) * uint64_t(settings.previewHeight) * uint64_t(settings.previewSpp));
  EXPECT_EQ(preview["non_finite_samples"].get<uint64_t>(), 0u);
  EXPECT_TRUE(fs::exists(dir / "preview.png"));
  EXPECT_TRUE(fs::exists(dir / "preview.exr"));
  cli_runner::expectMentions(section.html, {"grey/preview.png", "on the preview scene"});
}

// The section looks at no type: a subsurface description is rendered when the renderer accepts it.
TEST(LabRenders, ADescriptionOfAnyTypeIsRenderedWhenTheRendererAcceptsIt) {
  const fs::path dir = freshDir("lab-renders-any-type");
  LabMaterial skin = describedLabMaterial("skin", {{"type", "subsurface"}});
  skin.folder = "skin";
  const ReportSection section =
      rendersSection(skin, nullptr, tinyRenders(), furnace(), dir, {}, acceptEverything);
  EXPECT_EQ(renderRefusal(section), "");
  ASSERT_EQ(section.data["renders"].size(), 1u);
  // Albedo 0.5 under radiance 1: exactly 0.5 on the sphere (float pixels).
  for (const json& channel : section.data["renders"][0]["sphere_mean_rgb"])
    EXPECT_NEAR(channel.get<double>(), 0.5, 1e-6);
  EXPECT_TRUE(fs::exists(dir / "render_furnace_material.png"));
  EXPECT_TRUE(fs::exists(dir / "render_furnace_material.exr"));
}

// Samples the film drops are counted per render and shown in a red box; the images hold none.
TEST(LabRenders, DroppedSamplesAreCountedAndShownInARedBox) {
  const fs::path dir = freshDir("lab-renders-dropped");
  const SphereSceneFactory broken = [](const json&, const Environment& environment, int size) {
    return makePresetScene(ScenePreset::MaterialSphere,
                           std::make_unique<test_models::FaultyWeightLambertian>(1.0), environment, size,
                           size);
  };
  const LabSettings settings = tinyRenders();
  const ReportSection section =
      rendersSection(lambertian(0.5), nullptr, settings, furnace(), dir, {}, broken);
  ASSERT_EQ(section.data["renders"].size(), 1u);
  const json& render = section.data["renders"][0];
  const uint64_t dropped = render["dropped_samples"].get<uint64_t>();
  // Every sample that meets the sphere: at least all of its inner pixels' (the silhouette's
  // pixels are partly background), none of the background's.
  EXPECT_GE(dropped, render["sphere_pixels"].get<uint64_t>() * uint64_t(settings.renderSpp));
  EXPECT_LT(dropped, render["samples"].get<uint64_t>());
  EXPECT_EQ(render["non_finite_samples"].get<uint64_t>(), dropped);
  EXPECT_EQ(section.data["dropped_samples"].get<uint64_t>(), dropped);
  cli_runner::expectMentions(
      section.html,
      {"class=\"failures\"", "Samples dropped",
       std::to_string(dropped) + " of " + std::to_string(render["samples"].get<uint64_t>()) + " samples"});
  // The control: the same section of a sound material has no box.
  const ReportSection sound = rendersSection(lambertian(0.5), nullptr, settings, furnace(),
                                             freshDir("lab-renders-sound"), {}, acceptEverything);
  EXPECT_EQ(sound.data["dropped_samples"].get<uint64_t>(), 0u);
  EXPECT_EQ(sound.html.find("Samples dropped"), std::string::npos);
}

// The preview render's dropped samples are counted with the sphere renders': in its entry, in the
// section's total (which fails the material, lab_command.cpp) and in the red box.
TEST(LabRenders, DroppedSamplesOfThePreviewAreCountedAndShownInTheRedBox) {
  const fs::path dir = freshDir("lab-renders-preview-dropped");
  const PreviewSceneFactory brokenPreview = [](const json&, const Environment& environment, int width,
                                               int height) {
    return makePresetScene(ScenePreset::Preview, std::make_unique<test_models::FaultyWeightLambertian>(1.0),
                           environment, width, height);
  };
  const ReportSection section = rendersSection(lambertian(0.5), nullptr, tinyRenders(), furnace(), dir, {},
                                               acceptEverything, brokenPreview);
  ASSERT_EQ(section.data["renders"].size(), 1u);
  EXPECT_EQ(section.data["renders"][0]["dropped_samples"].get<uint64_t>(), 0u);
  const json& preview = section.data["preview"];
  ASSERT_TRUE(preview.is_object());
  const uint64_t dropped = preview["dropped_samples"].get<uint64_t>();
  // The sphere covers part of the preview: some of its samples, not all.
  EXPECT_GT(dropped, 0u);
  EXPECT_LT(dropped, preview["samples"].get<uint64_t>());
  EXPECT_EQ(preview["non_finite_samples"].get<uint64_t>(), dropped);
  EXPECT_EQ(preview["negative_samples"].get<uint64_t>(), 0u);
  EXPECT_EQ(section.data["dropped_samples"].get<uint64_t>(), dropped);
  cli_runner::expectMentions(section.html,
                             {"class=\"failures\"", "Samples dropped",
                              "on the preview scene: " + std::to_string(dropped) + " of " +
                                  std::to_string(preview["samples"].get<uint64_t>()) + " samples"});
}

// The integrator's material sphere refuses what makeBsdf refuses, with the registry's message.
TEST(LabRenders, TheIntegratorsSphereSceneRefusesWhatTheRegistryCannotMakeABsdfOf) {
  const json notABsdf{{"type", "no-such-model"}};
  std::string registryMessage;
  try {
    makeBsdf(notABsdf);
  } catch (const MaterialError& error) {
    registryMessage = error.what();
  }
  ASSERT_FALSE(registryMessage.empty());
  LabMaterial m = lambertian(0.5);
  m.description = notABsdf;
  const ReportSection section =
      rendersSection(m, nullptr, tinyRenders(), furnace(), freshDir("lab-renders-registry"), {});
  EXPECT_EQ(renderRefusal(section), registryMessage);
}

// A fit identical to the material renders the same bits (same seed); a fit of albedo 0.25
// against 0.5 differs by exactly half the material's value, with no noise under the furnace.
// A fit without a description is listed with its problem.
TEST(LabRenders, FitsAreRenderedBesideTheMaterialWithTheirDifference) {
  const fs::path dir = freshDir("lab-renders-fits");
  const LabMaterial material = lambertian(0.5);
  MaterialFits fits;
  fits.families.resize(3);
  fits.families[0].name = "same";
  fits.families[0].written.material = material.description;
  fits.families[1].name = "darker";
  fits.families[1].written.material =
      completeMaterial({{"type", "lambertian"}, {"albedo", {0.25, 0.25, 0.25}}});
  fits.families[2].name = "unwritten";
  fits.families[2].written.problem = "the fit did not converge (test)";
  const ReportSection section = rendersSection(material, &fits, tinyRenders(), furnace(), dir, {});
  ASSERT_EQ(section.data["renders"].size(), 3u);
  ASSERT_EQ(section.data["differences"].size(), 2u);
  const json& same = section.data["differences"][0];
  EXPECT_EQ(same["relative_mean_abs_difference"].get<double>(), 0.0);
  EXPECT_NEAR(same["relative_rms_noise"].get<double>(), 0.0,
              1e-6);  // a variance of equal floats: rounding only
  const json& darker = section.data["differences"][1];
  EXPECT_NEAR(darker["relative_mean_abs_difference"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(darker["relative_rms_difference"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(darker["relative_rms_noise"].get<double>(), 0.0, 1e-6);
  for (const char* file :
       {"render_furnace_fit2.png", "difference_furnace_fit2.png", "difference_furnace_fit2.exr"})
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  ASSERT_EQ(section.data["refused"].size(), 1u);
  EXPECT_EQ(section.data["refused"][0]["message"], "the fit did not converge (test)");
  EXPECT_EQ(renderRefusal(section), "");  // the material itself was rendered
  EXPECT_EQ(closestFitInRenders(section), "same: 0% (furnace)");
  cli_runner::expectMentions(section.html, {"Not rendered: unwritten", "the fit did not converge (test)"});
}

TEST(LabRenders, AnUnreadableEnvironmentMapNamesTheFile) {
  const fs::path missing = cli_runner::uniquePath("lab-renders-env") / "nowhere.exr";
  try {
    loadLabEnvironments({missing.string()});
    FAIL() << "no error for " << missing;
  } catch (const InputError& error) {
    cli_runner::expectMentions(error.what(), {"--env", missing.string()});
  }
}

}  // namespace lab_renders_test
}  // namespace scatterlab
