// The built-in scenes.
//
// "sphere": the peers' material-sphere scene (bench/cycles/README.md, cycles_sphere.py): a unit sphere
// at the origin, a pinhole camera at (0, -4, 0) looking at it with +Z up and a 45 degree field
// of view, the environment all around. Blender's UV sphere there is a mesh of 256 x 128
// segments; here it is the exact sphere.
//
// "preview": the same sphere resting on a ground plane z = -1 with a grey checkerboard
// (Lambertian, albedo 0.8 and 0.2 in squares of 0.5 units), seen from slightly above.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "integrator/scene.h"

namespace scatterlab {

enum class ScenePreset { MaterialSphere, Preview };

// "sphere" and "preview"; what the command line accepts.
std::vector<std::string> scenePresetNames();
// The preset called `name`, or nothing.
std::optional<ScenePreset> findScenePreset(std::string_view name);
std::string toString(ScenePreset preset);

struct MaterialSphereSetup {
  static constexpr double CameraDistance = 4.0;
  static constexpr double FovDegrees = 45.0;
  static constexpr double SphereRadius = 1.0;
};

// The preset with `material` on the sphere, lit by `environment`, seen at width x height.
Scene makePresetScene(ScenePreset preset, std::unique_ptr<BsdfModel> material, Environment environment,
                      int width, int height);
// The same with a subsurface material on the sphere, rendered in `mode` (subsurface.h).
Scene makePresetScene(ScenePreset preset, const SubsurfaceMaterial& material, SubsurfaceMode mode,
                      Environment environment, int width, int height);

// The sphere of every preset (the unit sphere at the origin), e.g. for silhouette masks.
Sphere presetSphere();

}  // namespace scatterlab
