// The renderer's answer to "can you render this material?": a registry material (JSON,
// materials/registry/) made into what the renderer places on a shape, and the preset
// scene with it on its sphere, or MaterialError saying why not.
//
// Callers that hold a material description and want its picture (`scatterlab render`, the lab
// report's renders) ask here instead of looking at the material's type, so that a kind of
// material the renderer learns to render appears everywhere at once. What it renders: every
// BSDF of the registry, and subsurface materials (integrator/subsurface.h) whose boundary the
// renderer supports.
#pragma once

#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "integrator/environment.h"
#include "integrator/scene.h"
#include "integrator/scene_presets.h"
#include "integrator/subsurface.h"
#include "materials/bsdf/bsdf.h"
#include "materials/bssrdf/subsurface_registry.h"

namespace scatterlab {

// Exactly one of the two is set.
struct RenderableMaterial {
  std::unique_ptr<BsdfModel> bsdf;
  std::optional<SubsurfaceMaterial> subsurface;
};

// Throws MaterialError (an invalid description, or one the renderer cannot render) with a
// message naming the key and what is allowed.
RenderableMaterial makeRenderableMaterial(const nlohmann::json& material);

// The preset scene with the material on its sphere, lit by `lighting`; a subsurface material is
// rendered in `mode`.
Scene makeMaterialScene(ScenePreset preset, RenderableMaterial material, SubsurfaceMode mode,
                        PresetLighting lighting, int width, int height);

// makeRenderableMaterial, then the preset scene in its own lighting around `environment`
// (presetLighting; subsurface materials in the diffusion mode).
Scene makeMaterialScene(ScenePreset preset, const nlohmann::json& material, Environment environment,
                        int width, int height);

}  // namespace scatterlab
