// The built-in scenes.
//
// "sphere": the peers' material-sphere scene (bench/cycles/README.md, cycles_sphere.py): a unit sphere
// at the origin, a pinhole camera at (0, -4, 0) looking at it with +Z up and a 45 degree field
// of view, the environment all around. Blender's UV sphere there is a mesh of 256 x 128
// segments; here it is the exact sphere.
//
// "preview": the classic material preview: the same sphere resting on a ground plane z = -1
// with a grey checkerboard (Lambertian, albedo 0.8 and 0.2 in squares of 0.5 units), seen from
// slightly above, under the environment and a small sphere light (PresetLight) to the right of
// it, which casts a contact shadow and, through a transparent sphere, a caustic on the ground.
//
// "caustic": the sphere on a plain grey ground (Lambertian, albedo 0.5), lit by that light
// alone (no environment unless one is given): with glass on the sphere, the caustic the
// sphere focuses on the ground, left of its shadow, is what the camera sees.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "integrator/scene.h"

namespace scatterlab {

enum class ScenePreset { MaterialSphere, Preview, Caustic };

// "sphere", "preview" and "caustic"; what the command line accepts.
std::vector<std::string> scenePresetNames();
// The preset called `name`, or nothing.
std::optional<ScenePreset> findScenePreset(std::string_view name);
std::string toString(ScenePreset preset);

struct MaterialSphereSetup {
  static constexpr double CameraDistance = 4.0;
  static constexpr double FovDegrees = 45.0;
  static constexpr double SphereRadius = 1.0;
};

// The small sphere light of the preview and caustic scenes. By default it sits 3.9 units from
// the sphere's centre, to its right and above, outside the camera's view; the line from it
// through the centre meets the ground 1.56 units from the centre, near the 1.5 units where a
// glass ball (eta 1.5) focuses, so the caustic is sharp; radiance 500 gives the sphere about
// twice the irradiance a white environment of radiance 1 gives from above (pi).
struct PresetLight {
  Vec3d position{3.0, 0.0, 2.5};
  double radius = 0.25;
  Rgb radiance{500.0};
};

// How a preset is lit: an environment (none: a black background) and the area light (none:
// removed). Presets differ in their defaults (presetLighting).
struct PresetLighting {
  std::optional<Environment> environment;
  std::optional<PresetLight> light;
};
// The preset's own lighting around `environment`: the sphere scene has no area light; the
// preview and caustic scenes have the default PresetLight.
PresetLighting presetLighting(ScenePreset preset, std::optional<Environment> environment);

// The preset with `material` on the sphere, lit by `lighting`, seen at width x height.
Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, PresetLighting lighting,
                      int width, int height);
// The same with a subsurface material on the sphere, rendered in `mode` (subsurface.h).
Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      PresetLighting lighting, int width, int height);
// The preset's own lighting with `environment` (presetLighting).
Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, Environment environment,
                      int width, int height);
Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      Environment environment, int width, int height);

// The sphere of every preset (the unit sphere at the origin), e.g. for silhouette masks.
Sphere presetSphere();

// Where the line from `light` through the sphere's centre meets the ground: the middle of the
// caustic a glass sphere throws (near it, for a ball lens that does not focus on the ground).
Vec3d causticCentre(const PresetLight& light = PresetLight{});
// The preview and caustic scenes' camera narrowed to `fovDegrees` around causticCentre(), so
// that every pixel of a width x height image looks at the caustic (the estimators' tests and
// benchmarks).
PinholeCamera causticCloseUp(int width, int height, double fovDegrees = 12.0);

}  // namespace scatterlab
