#include "integrator/material_scene.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "materials/registry/spec_validation.h"

namespace scatterlab {

RenderableMaterial makeRenderableMaterial(const nlohmann::json& material) {
  if (!isSubsurfaceMaterial(material)) return {makeBsdf(material), std::nullopt};
  SubsurfaceMaterial subsurface = makeSubsurface(material);
  try {
    makeSubsurfaceBoundary(subsurface);  // the renderer's own limits on the boundary
  } catch (const std::invalid_argument& error) {
    throw MaterialError(std::string("\"boundary\": ") + error.what());
  }
  return {nullptr, std::move(subsurface)};
}

Scene makeMaterialScene(ScenePreset preset, RenderableMaterial material, SubsurfaceMode mode,
                        PresetLighting lighting, int width, int height) {
  if (material.subsurface)
    return makePresetScene(preset, *material.subsurface, mode, std::move(lighting), width, height);
  return makePresetScene(preset, std::move(material.bsdf), std::move(lighting), width, height);
}

Scene makeMaterialScene(ScenePreset preset, const nlohmann::json& material, Environment environment,
                        int width, int height) {
  return makeMaterialScene(preset, makeRenderableMaterial(material), SubsurfaceMode::Diffusion,
                           presetLighting(preset, std::move(environment)), width, height);
}

}  // namespace scatterlab
