#include "integrator/material_scene.h"

#include <stdexcept>
#include <string>

#include "integrator/subsurface.h"
#include "materials/bsdf/registry.h"
#include "materials/bssrdf/subsurface_registry.h"

namespace scatterlab {

Scene makeMaterialScene(ScenePreset preset, const nlohmann::json& material, Environment environment, int width,
                        int height) {
  if (!isSubsurfaceMaterial(material))
    return makePresetScene(preset, makeBsdf(material), std::move(environment), width, height);
  const SubsurfaceMaterial subsurface = makeSubsurface(material);
  try {
    makeSubsurfaceBoundary(subsurface);  // the renderer's own limits on the boundary, as `scatterlab render`
  } catch (const std::invalid_argument& error) {
    throw MaterialError(std::string("\"boundary\": ") + error.what());
  }
  return makePresetScene(preset, subsurface, SubsurfaceMode::Diffusion, std::move(environment), width, height);
}

}  // namespace scatterlab
