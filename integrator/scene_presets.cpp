#include "integrator/scene_presets.h"

#include "materials/bsdf/lambertian.h"

namespace scatterlab {

std::vector<std::string> scenePresetNames() { return {"sphere", "preview"}; }

std::optional<ScenePreset> findScenePreset(std::string_view name) {
  if (name == "sphere") return ScenePreset::MaterialSphere;
  if (name == "preview") return ScenePreset::Preview;
  return std::nullopt;
}

std::string toString(ScenePreset preset) {
  return preset == ScenePreset::MaterialSphere ? "sphere" : "preview";
}

Sphere presetSphere() { return Sphere{Vec3d(0.0), MaterialSphereSetup::SphereRadius, Vec3d(0, 0, 1)}; }

namespace {

// The preset around a scene whose sphere already wears `material`.
Scene finishPresetScene(Scene scene, int material, ScenePreset preset, Environment environment, int width,
                        int height) {
  scene.addSphere(presetSphere(), material);
  scene.setEnvironment(std::move(environment));
  const Vec3d up(0, 0, 1);
  if (preset == ScenePreset::MaterialSphere) {
    scene.setCamera(PinholeCamera::lookAt(Vec3d(0, -MaterialSphereSetup::CameraDistance, 0), Vec3d(0.0), up,
                                          MaterialSphereSetup::FovDegrees, width, height));
    return scene;
  }
  const int ground = scene.addCheckerMaterial(std::make_unique<LambertianBsdf>(Rgb(0.8)),
                                              std::make_unique<LambertianBsdf>(Rgb(0.2)), 0.5);
  scene.addPlane(Plane{Vec3d(0, 0, -MaterialSphereSetup::SphereRadius), Vec3d(0, 0, 1), Vec3d(1, 0, 0)},
                 ground);
  scene.setCamera(PinholeCamera::lookAt(Vec3d(0, -5.0, 1.6), Vec3d(0, 0, -0.3), up, 40.0, width, height));
  return scene;
}

}  // namespace

Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, Environment environment,
                      int width, int height) {
  Scene scene;
  const int id = scene.addMaterial(std::move(material));
  return finishPresetScene(std::move(scene), id, preset, std::move(environment), width, height);
}

Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      Environment environment, int width, int height) {
  Scene scene;
  const int id = scene.addSubsurfaceMaterial(material, mode);
  return finishPresetScene(std::move(scene), id, preset, std::move(environment), width, height);
}

}  // namespace scatterlab
