// Bidirectional path tracing with every connection strategy and multiple importance sampling
// (bdpt.cpp). Renders with RenderSettings as the path tracer does (render.h dispatches here):
// maxDepth bounces per path, the variance layer of splat_film.h.
#pragma once

#include <functional>

#include "integrator/render.h"

namespace scatterlab {

RenderResult renderBdpt(const Scene& scene, const RenderSettings& settings,
                        const std::function<void(double)>& progress);

}  // namespace scatterlab
