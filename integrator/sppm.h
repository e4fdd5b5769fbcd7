// Stochastic progressive photon mapping (Hachisuka & Jensen 2009), the estimator for caustics
// that no camera path finds well (sppm.cpp). samplesPerPixel iterations, each a camera pass
// (one ray per pixel to its visible point, direct light there by next-event estimation) and a
// photon pass (photons from the lights, emission.h, carrying importance), after which every
// pixel's gather radius shrinks. Consistent, not unbiased: the bias of the kernel estimate
// vanishes as the radius does. No variance layer (its error is not a sample variance).
#pragma once

#include <functional>

#include "integrator/render.h"

namespace scatterlab {

RenderResult renderSppm(const Scene& scene, const RenderSettings& settings,
                        const std::function<void(double)>& progress);

// The gather radius SPPM starts from (scene units): settings.sppm.initialRadiusPixels pixel
// footprints at the distance from the eye to the centre of the scene's finite shapes.
double sppmInitialRadius(const Scene& scene, const SppmSettings& settings);

}  // namespace scatterlab
