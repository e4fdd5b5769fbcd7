// makeRenderableMaterial / makeMaterialScene: the one place that decides what the renderer
// renders, shared by `scatterlab render` and the lab report.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "integrator/material_scene.h"
#include "integrator/render.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {
namespace material_scene_test {

using nlohmann::json;

TEST(MaterialScene, ABsdfDescriptionBecomesABsdf) {
  const RenderableMaterial material = makeRenderableMaterial(json{{"type", "conductor"}});
  EXPECT_NE(material.bsdf, nullptr);
  EXPECT_FALSE(material.subsurface.has_value());
}

TEST(MaterialScene, ASubsurfaceDescriptionBecomesASubsurfaceMaterial) {
  const RenderableMaterial material =
      makeRenderableMaterial(json{{"type", "subsurface"}, {"medium", "Skin1"}});
  EXPECT_EQ(material.bsdf, nullptr);
  EXPECT_TRUE(material.subsurface.has_value());
}

// The rough boundary is a rough dielectric, whose range starts at eta 1.02
// (RoughDielectricIndexRange): the material is refused when it is read, naming the key and the
// allowed range.
TEST(MaterialScene, ARoughBoundaryTooCloseToIndexMatchedIsRefusedWithItsRange) {
  const json material{{"type", "subsurface"}, {"boundary", "rough"}, {"eta", 1.01}};
  try {
    makeRenderableMaterial(material);
    FAIL() << "accepted " << material.dump();
  } catch (const MaterialError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("\"eta\""), std::string::npos) << message;
    EXPECT_NE(message.find("[1.02, 4]"), std::string::npos) << message;
    EXPECT_NE(message.find("rough boundary"), std::string::npos) << message;
  }
}

TEST(MaterialScene, AnUnknownTypeIsRefused) {
  EXPECT_THROW(makeRenderableMaterial(json{{"type", "no-such-model"}}), MaterialError);
}

// Both kinds reach the same scene: in a white furnace a white Lambertian sphere is exactly 1 at
// one sample (its BSDF sampling weight is 1), and a subsurface sphere renders finite values.
TEST(MaterialScene, BothKindsRenderOnThePresetSphere) {
  RenderSettings settings;
  settings.samplesPerPixel = 1;
  settings.seed = 3;
  settings.threads = 1;
  const Scene lambertian =
      makeMaterialScene(ScenePreset::MaterialSphere, json{{"type", "lambertian"}, {"albedo", 1.0}},
                        Environment::constant(Rgb(1.0)), 8, 8);
  const RenderResult white = render(lambertian, settings, {});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_NEAR(white.color.rgb(x, y).x, 1.0, 1e-6) << x << ", " << y;
  const Scene skin = makeMaterialScene(
      ScenePreset::MaterialSphere, makeRenderableMaterial(json{{"type", "subsurface"}, {"medium", "Skin1"}}),
      SubsurfaceMode::RandomWalk,
      presetLighting(ScenePreset::MaterialSphere, Environment::constant(Rgb(1.0))), 8, 8);
  const RenderResult walked = render(skin, settings, {});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(std::isfinite(walked.color.rgb(x, y).x)) << x << ", " << y;
}

}  // namespace material_scene_test
}  // namespace scatterlab
