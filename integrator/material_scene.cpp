#include "integrator/material_scene.h"

#include <stdexcept>
#include <string>

#include "materials/bsdf/registry.h"

// The subsurface part of the renderer (integrator/subsurface.h) arrives with the bssrdf work;
// where it is built in, subsurface materials are rendered, and nothing else has to change.
#if __has_include("integrator/subsurface.h")
#include "integrator/subsurface.h"
#include "materials/bssrdf/subsurface_registry.h"
#define SCATTERLAB_RENDERS_SUBSURFACE 1
#else
#define SCATTERLAB_RENDERS_SUBSURFACE 0
#endif

namespace scatterlab {

Scene makeMaterialScene(ScenePreset preset, const nlohmann::json& material, Environment environment, int width,
                        int height) {
#if SCATTERLAB_RENDERS_SUBSURFACE
  if (isSubsurfaceMaterial(material)) {
    const SubsurfaceMaterial subsurface = makeSubsurface(material);
    try {
      makeSubsurfaceBoundary(subsurface);  // the renderer's own limits on the boundary, as `scatterlab render`
    } catch (const std::invalid_argument& error) {
      throw MaterialError(std::string("\"boundary\": ") + error.what());
    }
    return makePresetScene(preset, subsurface, SubsurfaceMode::Diffusion, std::move(environment), width, height);
  }
#endif
  return makePresetScene(preset, makeBsdf(material), std::move(environment), width, height);
}

}  // namespace scatterlab
