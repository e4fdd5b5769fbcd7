// The scene: nearest hits among spheres and planes, occlusion, probes against one shape,
// checkerboard materials, spheres placed by transforms, light selection, and the presets.
#include <gtest/gtest.h>

#include "integrator/scene_presets.h"
#include "materials/bsdf/lambertian.h"

namespace scatterlab {
namespace scene_test {

Scene twoShapes() {
  Scene scene;
  const int grey = scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5)));
  scene.addSphere(Sphere{Vec3d(0, 0, 0), 1.0}, grey);
  scene.addPlane(Plane{Vec3d(0, 0, -1), Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, grey);
  return scene;
}

TEST(Scene, FindsTheNearestShape) {
  const Scene scene = twoShapes();
  const auto top = scene.intersect({Vec3d(0, 0, 5), Vec3d(0, 0, -1)});
  ASSERT_TRUE(top);
  EXPECT_EQ(top->shape, 0);
  EXPECT_DOUBLE_EQ(top->t, 4.0);
  const auto side = scene.intersect({Vec3d(3, 0, 5), Vec3d(0, 0, -1)});
  ASSERT_TRUE(side);
  EXPECT_EQ(side->shape, 1);
  EXPECT_DOUBLE_EQ(side->t, 6.0);
  EXPECT_FALSE(scene.intersect({Vec3d(3, 0, 5), Vec3d(0, 0, 1)}));
  EXPECT_TRUE(scene.occluded({Vec3d(0, 0, 5), Vec3d(0, 0, -1)}, 4.5));
  EXPECT_FALSE(scene.occluded({Vec3d(0, 0, 5), Vec3d(0, 0, -1)}, 3.5));
  // A probe against the plane alone passes through the sphere.
  EXPECT_DOUBLE_EQ(scene.intersectShape(1, {Vec3d(0, 0, 5), Vec3d(0, 0, -1)}, 0.0, Infinity), 6.0);
  EXPECT_DOUBLE_EQ(scene.intersectShape(0, {Vec3d(0, 0, 5), Vec3d(0, 0, -1)}, 4.5, Infinity), 6.0);
}

TEST(Scene, CheckerboardAlternatesModels) {
  Scene scene;
  auto even = std::make_unique<LambertianBsdf>(Rgb(0.8));
  auto odd = std::make_unique<LambertianBsdf>(Rgb(0.2));
  const BsdfModel *evenModel = even.get(), *oddModel = odd.get();
  scene.addPlane(Plane{Vec3d(0.0), Vec3d(0, 0, 1), Vec3d(1, 0, 0)},
                 scene.addCheckerMaterial(std::move(even), std::move(odd), 0.5));
  const auto modelAt = [&](double x, double y) {
    return scene.intersect({Vec3d(x, y, 1), Vec3d(0, 0, -1)})->model;
  };
  EXPECT_EQ(modelAt(0.25, 0.25), evenModel);
  EXPECT_EQ(modelAt(0.75, 0.25), oddModel);
  EXPECT_EQ(modelAt(-0.25, 0.25), oddModel);
  EXPECT_EQ(modelAt(-0.25, -0.25), evenModel);
  EXPECT_EQ(modelAt(1.25, 0.75), oddModel);
}

TEST(Scene, PlacesSpheresBySimilarities) {
  Scene scene;
  const int grey = scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5)));
  scene.addSphere(
      Transform::translate(Vec3d(0, 5, 0)) * Transform::rotate(90, Vec3d(1, 0, 0)) * Transform::scale(2.0),
      grey);
  const auto hit = scene.intersect({Vec3d(0.0), Vec3d(0, 1, 0)});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 3.0, 1e-12);
  // The object's z axis now points along -y: tangents circle it.
  const auto side = scene.intersect({Vec3d(0, 5, 5), Vec3d(0, 0, -1)});
  EXPECT_NEAR(std::abs(side->geometry.tangent.x), 1.0, 1e-12);
  const Transform shear(glm::dmat4(1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
  EXPECT_THROW(scene.addSphere(shear, grey), std::invalid_argument);
}

TEST(Scene, ChoosesLightsUniformly) {
  Scene scene;
  scene.setEnvironment(Environment::constant(Rgb(1.0)));
  scene.addSphereLight(Sphere{Vec3d(0, 0, 10), 1.0}, Rgb(5.0));
  scene.addSun(SunLight(Vec3d(1, 0, 1), Rgb(2.0), 5.0));
  ASSERT_EQ(scene.lightCount(), 3);
  const Vec3d p(0.0);
  const auto env = scene.sampleLight(p, 0.1, {0.3, 0.3});
  EXPECT_DOUBLE_EQ(env->pdf, 1.0 / (4 * Pi) / 3.0);
  const auto sphere = scene.sampleLight(p, 0.5, {0.3, 0.3});
  EXPECT_DOUBLE_EQ(sphere->pdf, scene.sphereLights()[0].pdf(p) / 3.0);
  EXPECT_EQ(sphere->radiance, Rgb(5.0));
  const auto sun = scene.sampleLight(p, 0.9, {0.3, 0.3});
  EXPECT_DOUBLE_EQ(sun->pdf, scene.suns()[0].pdf(sun->direction) / 3.0);
  // The sphere light's surface is an emitter seen from outside only, and reflects nothing.
  const auto hit = scene.intersect({Vec3d(0.0), Vec3d(0, 0, 1)});
  ASSERT_TRUE(hit);
  EXPECT_EQ(scene.emitted(*hit, Vec3d(0, 0, -1)), Rgb(5.0));
  EXPECT_EQ(hit->model->eval(Vec3d(0, 0, 1), Vec3d(0, 0, 1)), Rgb(0.0));
  EXPECT_DOUBLE_EQ(scene.emittedPdf(*hit, p), scene.sphereLights()[0].pdf(p) / 3.0);
}

TEST(ScenePresets, AreThePeersSceneThePreviewAndTheCaustic) {
  EXPECT_EQ(findScenePreset("sphere"), ScenePreset::MaterialSphere);
  EXPECT_EQ(findScenePreset("preview"), ScenePreset::Preview);
  EXPECT_EQ(findScenePreset("caustic"), ScenePreset::Caustic);
  EXPECT_FALSE(findScenePreset("cornell"));
  const Scene sphere = makePresetScene(ScenePreset::MaterialSphere,
                                       std::make_unique<LambertianBsdf>(Rgb(1.0)), Environment(), 64, 48);
  EXPECT_EQ(sphere.shapeCount(), 1);
  EXPECT_EQ(sphere.lightCount(), 1);  // the environment alone
  EXPECT_EQ(sphere.camera().eye(), Vec3d(0, -4, 0));
  EXPECT_EQ(sphere.camera().fovDegrees(), 45.0);
  EXPECT_EQ(sphere.camera().width(), 64);
  const Scene preview = makePresetScene(ScenePreset::Preview, std::make_unique<LambertianBsdf>(Rgb(1.0)),
                                        Environment(), 64, 48);
  // The sphere, the sphere light and the ground; the environment and the light.
  EXPECT_EQ(preview.shapeCount(), 3);
  EXPECT_EQ(preview.lightCount(), 2);
  EXPECT_EQ(preview.sphereLights()[0].sphere.center, PresetLight{}.position);
  // The sphere rests on the ground.
  EXPECT_DOUBLE_EQ(preview.intersectShape(2, {Vec3d(0, 0, 5), Vec3d(0, 0, -1)}, 0.0, Infinity), 6.0);
  // The caustic scene: the light alone unless an environment is given; a plain grey ground.
  const Scene caustic = makePresetScene(ScenePreset::Caustic, std::make_unique<LambertianBsdf>(Rgb(1.0)),
                                        presetLighting(ScenePreset::Caustic, std::nullopt), 64, 48);
  EXPECT_EQ(caustic.lightCount(), 1);
  EXPECT_EQ(caustic.environment(), nullptr);
  const std::optional<SurfaceInteraction> ground = caustic.intersect({Vec3d(2.5, 0.7, 5), Vec3d(0, 0, -1)});
  ASSERT_TRUE(ground);
  EXPECT_EQ(ground->model->eval(Vec3d(0, 0, 1), Vec3d(0, 0, 1)), Rgb(0.5 * InvPi));
  // A light removed or moved.
  const Scene dark = makePresetScene(ScenePreset::Preview, std::make_unique<LambertianBsdf>(Rgb(1.0)),
                                     PresetLighting{Environment(), std::nullopt}, 8, 8);
  EXPECT_EQ(dark.lightCount(), 1);
}

}  // namespace scene_test
}  // namespace scatterlab
