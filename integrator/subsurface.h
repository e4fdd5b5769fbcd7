// Subsurface materials in the path tracer: a dielectric boundary (smooth, or
// rough GGX with multiple-scattering compensation) around a homogeneous medium, rendered in one
// of two ways.
//
// Diffusion (the BSSRDF, separable_bssrdf.h). At the point xo the camera path reaches, the
// boundary is sampled; reflection continues as at any dielectric. Transmission stands for the
// factor Ft(wo) of S = Ft(wo) R(|xi - xo|) Ft(wi) / (pi c): its weight (Fresnel-chosen: 1 for the
// smooth boundary; the transmitted share for the rough one), without the 1/eta^2 radiance
// scaling, which the light undoes on its way out. The point xi where the light entered is then
// found by probe rays against the same shape (probe_sampling.h: King et al. 2013), one of the
// chord's k crossings chosen uniformly, with weight R(r) / (pdf(xi) / k). At xi the remaining
// directional factor Sw(wi) = Ft(wi) / (pi c) is a BSDF (subsurface_exit_bsdf.h) with NEE and
// cosine sampling under MIS, like any other vertex. The profile's lengths are the scene's units
// (the material's "scale"). What the probe misses (beyond r_max, the 0.999 quantile) is lost.
//
// Random walk (the reference). After a transmission the path enters the medium and walks in it:
// free flights, Henyey-Greenstein scattering, and at the boundary the same dielectric sampled
// from inside (reflection continues the walk, transmission leaves). Colour by single-sample
// spectral MIS (Chiang, Kutz & Burley 2016, "Practical and Controllable Subsurface Scattering
// for Production Path Tracing"): a channel c chosen with probability p_c proportional to the
// walk's weight in it draws the flight t ~ sigma_t,c exp(-sigma_t,c t), and every channel is
// weighted by its own density over the mixture sum_c p_c sigma_t,c exp(-sigma_t,c t) (the
// balance heuristic); choosing by the weight keeps a channel that has lost its light from
// steering the walk. Only the walk's own shape is searched: the shape must be closed and hold nothing
// else. Its events do not count as bounces; Russian roulette on the walk weight after
// WalkRouletteEvents events, and at most MaxWalkEvents (the path ends there).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "integrator/interaction.h"
#include "integrator/ray.h"
#include "integrator/sampler.h"
#include "integrator/shapes.h"
#include "materials/bssrdf/probe_sampling.h"
#include "materials/bssrdf/subsurface_exit_bsdf.h"
#include "materials/bssrdf/subsurface_material.h"

namespace scatterlab {

class Scene;

enum class SubsurfaceMode { Diffusion, RandomWalk };
std::vector<std::string> subsurfaceModeNames();  // "diffusion", "walk"
std::optional<SubsurfaceMode> findSubsurfaceMode(const std::string& name);
std::string toString(SubsurfaceMode mode);

inline constexpr int WalkRouletteEvents = 16;
inline constexpr int MaxWalkEvents = 10'000'000;

// The boundary model of a subsurface material: SmoothDielectricBsdf(eta), or for a rough
// boundary GGX with alpha = roughness and Kulla-Conty compensation (lossless); a rough boundary
// needs eta in [1.02, 4] (std::invalid_argument otherwise).
std::unique_ptr<BsdfModel> makeSubsurfaceBoundary(const SubsurfaceMaterial& material);

// What the scene keeps of a subsurface material (the boundary model is the scene's material).
struct SceneSubsurface {
  SceneSubsurface(const SubsurfaceMaterial& material, SubsurfaceMode mode, const BsdfModel& boundary);

  SubsurfaceMaterial material;
  SubsurfaceMode mode;
  const BsdfModel* boundary;
  ProbeSampler probe;       // over material.profile
  SubsurfaceExitBsdf exit;  // Sw at the probe's exit point
  Rgb sigmaS, sigmaT;       // scene units^-1
};

// Diffusion: the point where the light entered, found from `point` (normal `normal`) on shape
// `shape` by one probe ray, with weight R(r) / pdf. Nothing when the probe finds no surface.
struct DiffusionExit {
  Vec3d point;
  SurfaceGeometry geometry;
  Rgb weight;
};
std::optional<DiffusionExit> sampleDiffusionExit(const Scene& scene, int shape,
                                                 const SceneSubsurface& subsurface, const Vec3d& point,
                                                 const Vec3d& normal, SampleStream& random);

// Random walk along `inward` (from just inside shape `shape`: spawnRay) until it leaves
// by a transmission: the exit point, its outward normal, the outgoing direction and the walk's
// weight (flights, albedo, and the boundary's samples from inside). Nothing when the walk is
// absorbed (roulette), runs out of events or loses the shape.
struct WalkExit {
  Vec3d point;
  Vec3d normal;
  Vec3d direction;
  Rgb weight;
};
std::optional<WalkExit> walkThroughMedium(const Scene& scene, int shape, const SceneSubsurface& subsurface,
                                          const Ray& inward, SampleStream& random);

// ---- The camera path's continuation below the surface (path_tracer.cpp).

// True when the boundary's sample `sample` at `hit`, reached from the side of `wi`, transmits
// from outside into the medium of a subsurface material.
bool entersMedium(const SurfaceInteraction& hit, const Vec3d& wi, const BsdfSample& sample);

// Where the path comes out of the medium it entered by `sample` at `hit`, and the throughput's
// factor from the boundary sample (included) to there. Diffusion: the probe's exit point is a
// vertex of the path whose BSDF is Sw (`vertex`: next-event estimation and a direction sample
// happen there as at any surface); the boundary's weight is taken without the 1/eta^2 radiance
// scaling, which the light undoes on its way out. The walk: the path leaves along `ray`, found
// by no light sampling. Nothing when the light is lost (the probe misses, the walk is absorbed).
struct MediumExit {
  Rgb weight{1.0};
  std::optional<SurfaceInteraction> vertex;  // diffusion
  Ray ray{};                                 // the walk
};
std::optional<MediumExit> leaveMedium(const Scene& scene, const SurfaceInteraction& hit,
                                      const BsdfSample& sample, SampleStream& random);

}  // namespace scatterlab
