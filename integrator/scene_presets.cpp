#include "integrator/scene_presets.h"

#include "materials/bsdf/lambertian.h"

namespace scatterlab {

std::vector<std::string> scenePresetNames() { return {"sphere", "preview", "caustic"}; }

std::optional<ScenePreset> findScenePreset(std::string_view name) {
  if (name == "sphere") return ScenePreset::MaterialSphere;
  if (name == "preview") return ScenePreset::Preview;
  if (name == "caustic") return ScenePreset::Caustic;
  return std::nullopt;
}

std::string toString(ScenePreset preset) {
  switch (preset) {
    case ScenePreset::MaterialSphere: return "sphere";
    case ScenePreset::Preview: return "preview";
    case ScenePreset::Caustic: return "caustic";
  }
  return "sphere";
}

Sphere presetSphere() { return Sphere{Vec3d(0.0), MaterialSphereSetup::SphereRadius, Vec3d(0, 0, 1)}; }

namespace {

const Vec3d PreviewEye(0, -5.0, 1.6);
const Vec3d PreviewTarget(0, 0, -0.3);
constexpr double PreviewFovDegrees = 40.0;
constexpr double GroundZ = -MaterialSphereSetup::SphereRadius;

}  // namespace

Vec3d causticCentre(const PresetLight& light) {
  const Vec3d toLight = light.position - presetSphere().center;
  return presetSphere().center + toLight * (GroundZ / toLight.z);
}

PinholeCamera causticCloseUp(int width, int height, double fovDegrees) {
  return PinholeCamera::lookAt(PreviewEye, causticCentre(), Vec3d(0, 0, 1), fovDegrees, width, height);
}

PresetLighting presetLighting(ScenePreset preset, std::optional<Environment> environment) {
  PresetLighting lighting{std::move(environment), std::nullopt};
  if (preset != ScenePreset::MaterialSphere) lighting.light = PresetLight{};
  return lighting;
}

namespace {

// The preset around a scene whose sphere already wears `material`.
Scene finishPresetScene(Scene scene, int material, ScenePreset preset, PresetLighting lighting, int width,
                        int height) {
  scene.addSphere(presetSphere(), material);
  if (lighting.environment) scene.setEnvironment(std::move(*lighting.environment));
  if (lighting.light)
    scene.addSphereLight(Sphere{lighting.light->position, lighting.light->radius}, lighting.light->radiance);
  const Vec3d up(0, 0, 1);
  if (preset == ScenePreset::MaterialSphere) {
    scene.setCamera(PinholeCamera::lookAt(Vec3d(0, -MaterialSphereSetup::CameraDistance, 0), Vec3d(0.0), up,
                                          MaterialSphereSetup::FovDegrees, width, height));
    return scene;
  }
  const int ground = preset == ScenePreset::Preview
                         ? scene.addCheckerMaterial(std::make_unique<LambertianBsdf>(Rgb(0.8)),
                                                    std::make_unique<LambertianBsdf>(Rgb(0.2)), 0.5)
                         : scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5)));
  scene.addPlane(Plane{Vec3d(0, 0, GroundZ), Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, ground);
  scene.setCamera(PinholeCamera::lookAt(PreviewEye, PreviewTarget, up, PreviewFovDegrees, width, height));
  return scene;
}

}  // namespace

Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, PresetLighting lighting,
                      int width, int height) {
  Scene scene;
  const int id = scene.addMaterial(std::move(material));
  return finishPresetScene(std::move(scene), id, preset, std::move(lighting), width, height);
}

Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      PresetLighting lighting, int width, int height) {
  Scene scene;
  const int id = scene.addSubsurfaceMaterial(material, mode);
  return finishPresetScene(std::move(scene), id, preset, std::move(lighting), width, height);
}

Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, Environment environment,
                      int width, int height) {
  return makePresetScene(preset, std::move(material), presetLighting(preset, std::move(environment)), width,
                         height);
}

Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      Environment environment, int width, int height) {
  return makePresetScene(preset, material, mode, presetLighting(preset, std::move(environment)), width,
                         height);
}

}  // namespace scatterlab
