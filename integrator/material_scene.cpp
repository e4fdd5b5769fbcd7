#include "integrator/material_scene.h"

#include <utility>

#include "integrator/fault_injection.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

RenderableMaterial makeRenderableMaterial(const nlohmann::json& material) {
  if (!isSubsurfaceMaterial(material)) return {withTestFault(makeBsdf(material)), std::nullopt};
  // makeSubsurface has checked what the renderer needs of the boundary (a rough boundary's eta).
  return {nullptr, makeSubsurface(material)};
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
