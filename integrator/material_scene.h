// The renderer's answer to "can you render this material?": the preset scene with a registry
// material (JSON, materials/bsdf/registry.h) on its sphere, or MaterialError saying why not.
//
// Callers that hold a material description and want its picture (the lab report's renders)
// ask here instead of looking at the material's type, so that a kind of material the renderer
// learns to render appears everywhere at once. What it renders: every BSDF of the registry,
// and subsurface materials in the diffusion mode of integrator/subsurface.h (the BSSRDF
// itself, the model the lab's checks are about), except those whose boundary the renderer
// cannot take (a rough boundary needs eta in [1.02, 4]), which are refused with its message.
#pragma once

#include <nlohmann/json.hpp>

#include "integrator/environment.h"
#include "integrator/scene.h"
#include "integrator/scene_presets.h"

namespace scatterlab {

// Throws MaterialError (an invalid description, or one the renderer cannot render) with a
// message naming the key and what is allowed.
Scene makeMaterialScene(ScenePreset preset, const nlohmann::json& material, Environment environment, int width,
                        int height);

}  // namespace scatterlab
