// Unidirectional path tracing with next-event estimation (NEE) and multiple importance
// sampling (Veach 1997, ch. 9; pbrt-v4's PathIntegrator): at every vertex with a non-delta
// lobe one light is sampled and one BSDF direction is drawn, and emission found either way is
// weighted by the power heuristic (Veach 1997, eq. 9.13, beta = 2). Delta lobes (mirrors,
// smooth glass) skip NEE and count the emission they find in full. A transmissive model sees
// the side of wi as inside or outside (Bsdf(..., twoSided = false)), so the interior of a
// dielectric sphere needs no bookkeeping beyond the model's own. The camera path carries
// radiance (TransportMode::Radiance). Under MIS a constant environment is found by BSDF
// sampling alone (scene.h, LightSet).
//
// Depth: `maxDepth` scattering events (bounces) at most, as Cycles' max_bounces; emission
// reached after the last bounce still counts. Russian roulette from `rouletteDepth` bounces on,
// continuing with the throughput's largest channel as probability, the throughput measured
// without the 1/eta^2 radiance scaling of refractions (pbrt-v4's etaScale), so paths inside
// glass are not killed for a scaling that undoes itself on the way out.
//
// Estimators, for testing that they agree: Mis (the default), BsdfOnly (no NEE, emission
// counted wherever a BSDF-sampled ray finds it; a delta sun is then never found), LightOnly
// (direct light by NEE alone, emission counted only on camera rays and after delta bounces).
//
// Subsurface materials (subsurface.h) plug in where the boundary's sample is a transmission
// into the medium: in diffusion mode the exit point is found by probe rays against the same
// shape (Scene::intersectShape), the throughput takes the profile's weight, and the exit point
// is a vertex with NEE like any other; in random-walk mode the path walks through the medium
// and continues from where it leaves.
#pragma once

#include <cmath>
#include <cstdint>

#include "integrator/sampler.h"
#include "integrator/scene.h"

namespace scatterlab {

enum class Estimator { Mis, BsdfOnly, LightOnly };

struct IntegratorSettings {
  int maxDepth = 12;
  Estimator estimator = Estimator::Mis;
  int rouletteDepth = 3;
};

// What one camera sample carries back.
struct PathSample {
  Rgb radiance{0.0};
  Rgb albedo{0.0};        // the first vertex's BSDF sample weight f |cos| / pdf: an unbiased albedo estimate
  Vec3d normal{0.0};      // the first vertex's shading normal; 0 when the camera ray escapes
  uint32_t vertices = 0;  // surface hits along the path (shadow rays not counted)
};

// Veach's power heuristic for two strategies, the first evaluated (beta = 2), written as
// 1 / (1 + (pB / pA)^2) so that very narrow lobes (pdf ~1e12 and more) cannot overflow.
inline double powerHeuristic(double pdfA, double pdfB) {
  if (!(pdfA > 0)) return 0.0;
  const double ratio = pdfB / pdfA;
  return 1.0 / (1.0 + ratio * ratio);
}

// Next-event estimation at one vertex `hit` (BSDF `bsdf`, reached from the side of wi): one
// light of `lightSet` sampled, its contribution f L |cos| / pdf, weighted against BSDF sampling
// by the power heuristic (Mis) or in full (LightOnly, BsdfOnly). Three random numbers.
Rgb directLighting(const Scene& scene, const SurfaceInteraction& hit, const Bsdf& bsdf, const Vec3d& wi,
                   SampleStream& random, Estimator estimator, LightSet lightSet);

PathSample tracePath(const Scene& scene, const Ray& cameraRay, SampleStream& random,
                     const IntegratorSettings& settings);

}  // namespace scatterlab
