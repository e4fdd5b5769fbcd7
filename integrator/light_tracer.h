// Light tracing (particle tracing; Arvo & Kirk 1990, Dutre, Lafortune & Willems 1993): light
// paths from the lights, every vertex joined to the eye and added where it lands on the film
// (light_tracer.cpp). Renders with RenderSettings as the path tracer does (render.h dispatches
// here); the variance layer is splat_film.h's.
#pragma once

#include <functional>

#include "integrator/render.h"

namespace scatterlab {

RenderResult renderLightTracing(const Scene& scene, const RenderSettings& settings,
                                const std::function<void(double)>& progress);

}  // namespace scatterlab
