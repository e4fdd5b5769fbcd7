// The adjoint of a BSDF proven on a render (docs/validation.md section 7): path tracing carries
// radiance and calls a BSDF with TransportMode::Radiance; light tracing and BDPT's light
// subpaths carry importance and call it with TransportMode::Importance, f*(wi, wo) = f(wo, wi)
// with no 1/eta^2 at a refraction (Veach 1997, sec. 5.2 and 10.1). The three are unbiased
// estimators of the same image, so their renders of the preview scene (the material on the
// sphere, the checkered ground, a small sphere light; no environment, so that every path starts
// at the light) agree within noise exactly when every mode of the material is right.
//
// The statistic is the block chi-square of integrator/block_statistic.h with blocks of one
// pixel: the image is rendered at 16 x 12, because pixels of a splatting estimator are not
// independent (one light path adds to several pixels), while the film's variance of one pixel
// is exact (splat_film.h). Shared by `scatterlab check --render-agreement` and the adjoint
// agreement tests.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "integrator/block_statistic.h"
#include "integrator/render.h"
#include "materials/bsdf/bsdf.h"
#include "validation/check_report.h"

namespace scatterlab {

constexpr int RenderAgreementWidth = 16, RenderAgreementHeight = 12;
// Up to five comparisons (below) x three channels per material: the count of chi-square tests a
// Sidak correction must cover.
constexpr int RenderAgreementTestsPerMaterial = 15;

struct RenderAgreementOptions {
  // The path tracer's samples per pixel; the other renders scale with it (BDPT a quarter, light
  // tracing twice, light tracing of direct light 16 times). 1024 is what the tests use.
  int pathSpp = 1024;
};

RenderResult renderWith(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth);

// A light tracer's pixel that a few dozen light paths reach is far from normal (its splats
// are few, of unequal size, skewed to the right), and its variance estimate is 0 where none
// did; a path tracer's pixel where a few BSDF samples found the light through glass is the
// same. So two renders are compared where an independent pilot render of each (a quarter of
// the samples, another seed) predicts a relative standard error below 0.1 for the render
// compared: the equivalent of 100 equal contributions or more. The pilot is independent of the
// renders compared, so choosing pixels by it cannot bias the statistic.
struct PilotedRender {
  RenderResult render, pilot;
  bool reliable(int x, int y, int channel) const;
};
PilotedRender renderPiloted(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth);

// One comparison of two estimators: its worst channel, and where that channel's largest z is.
struct EstimatorPair {
  std::string name;
  Agreement worst;
  std::string largest;
};

// Pixel by pixel over the pixels and channels where include(x, y, channel) holds.
EstimatorPair comparePixels(const std::string& name, const RenderResult& a, const RenderResult& b,
                            const std::function<bool(int, int, int)>& include);

// Which estimator converges fastest on the material: per estimator, the seconds its render took
// times the relative variance of a typical pixel, / 1e-4: the seconds it would need to bring a
// typical pixel to 1% relative standard error (variance falls as 1 / samples, time grows with
// them).
struct ConvergenceSpeed {
  double path = 0.0, light = 0.0, bdpt = 0.0;  // seconds to 1% relative error per pixel
  int pixels = 0;
  std::string fastest() const;
};

struct RenderAgreement {
  std::vector<EstimatorPair> pairs;
  ConvergenceSpeed speed;
  uint64_t nonFiniteSamples = 0;  // over every render
  uint64_t negativeSamples = 0;   // over every render
  uint64_t droppedSamples() const { return nonFiniteSamples + negativeSamples; }
};

// A material, built as often as scenes need it.
using MaterialFactory = std::function<std::unique_ptr<BsdfModel>()>;

// Renders the preview scene with the material by the three estimators and compares them
// (render_agreement.cpp lists the comparisons). Deterministic for a seed.
RenderAgreement compareEstimators(const MaterialFactory& material, uint64_t seed,
                                  const RenderAgreementOptions& options = {});

// Each material its own random numbers (the ground looks the same under every material, and
// with one seed for all its fluctuations would be one event counted many times): FNV-1a of
// the name, spaced for the seven renders of compareEstimators.
uint64_t renderAgreementSeed(const std::string& name);

// The check rows of one material: one chi-square row per comparison (its worst channel; passes
// when p >= threshold and at least one pixel was compared) and a bound row for non-finite
// samples (none allowed). The fastest estimator is named in the first row's note.
CheckReport renderAgreementReport(const std::string& material, const RenderAgreement& agreement,
                                  double threshold);

}  // namespace scatterlab
