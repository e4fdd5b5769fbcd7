// The film and the render loop: every pixel's samples traced by one task, pixels grouped in
// 16 x 16 tiles spread over TBB workers; sample s of pixel p draws its random numbers from
// SampleStream(seed, p, s) and a pixel is the mean of its own samples (pixel_filter.h), so the
// image is the same bits for any thread count.
//
// Layers: colour (radiance), and on request the first vertex's albedo estimate and shading
// normal (means over the pixel's samples, 0 where the camera ray escapes: inputs for a
// denoiser) and the variance of the colour's pixel mean, s^2 / n with s^2 the unbiased sample
// variance per channel (0 when spp = 1, where it cannot be estimated). A sample whose value is
// not finite or has a negative channel (never expected: the tests check every catalog
// material) is dropped: it contributes 0 and is counted (RenderStatistics), so no NaN or
// infinity ever reaches the film and nothing is lost silently. Callers report the counts and
// fail when they are not 0.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "integrator/image.h"
#include "integrator/path_tracer.h"
#include "integrator/pixel_filter.h"
#include "integrator/scene.h"

namespace scatterlab {

// The estimator that renders the image: the path tracer (path_tracer.h), light tracing
// (light_tracer.h), bidirectional path tracing (bdpt.h) or stochastic progressive photon
// mapping (sppm.h). All four share the scene, the camera, the pixel filter and the lights.
enum class IntegratorKind { Path, Light, Bdpt, Sppm };
std::vector<std::string> integratorNames();  // "path", "light", "bdpt", "sppm"
std::optional<IntegratorKind> findIntegrator(std::string_view name);
std::string toString(IntegratorKind kind);

// Photon mapping's own settings (sppm.h).
struct SppmSettings {
  int64_t photonsPerIteration = 0;  // 0: one per pixel
  // The initial gather radius in pixels: a visible point's radius starts as this many pixel
  // footprints at its distance from the eye.
  double initialRadiusPixels = 2.0;
  double alpha = 2.0 / 3.0;  // the share of new photons kept per iteration (Hachisuka & Jensen 2009)
};

struct RenderSettings {
  IntegratorKind integratorKind = IntegratorKind::Path;
  // Samples per pixel; for SPPM, iterations (one camera ray per pixel and one photon pass each).
  int samplesPerPixel = 16;
  uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  PixelFilter filter = PixelFilter::box();
  IntegratorSettings
      integrator{};  // maxDepth and roulette for every estimator; `estimator` for the path tracer
  SppmSettings sppm{};
  bool albedoLayer = false, normalLayer = false, varianceLayer = false;
};

// Limits on what render() accepts (a pixel or sample index must fit SampleStream's 32 bits).
inline constexpr int MaxImageSide = 16384;
inline constexpr int64_t MaxImagePixels = int64_t(1)
                                          << 25;  // 8192 x 4096: 0.4 GB of colour, 1.6 GB with every layer
inline constexpr int MaxSamplesPerPixel = 1 << 20;
inline constexpr int MaxPathDepth = 1024;

// The film's rule for one path (sample_value.h): dropped when the path ended on an invalid
// weight, or when its radiance or albedo estimate is not finite or negative.
SampleValue classifySample(const PathSample& path);

struct RenderStatistics {
  uint64_t samples = 0;
  uint64_t vertices = 0;          // surface hits of every path
  uint64_t nonFiniteSamples = 0;  // samples dropped as non-finite (expected 0)
  uint64_t negativeSamples = 0;   // samples dropped for a negative channel (expected 0)
  double seconds = 0.0;           // wall time of the path tracing

  uint64_t droppedSamples() const { return nonFiniteSamples + negativeSamples; }
  void count(SampleValue value) {
    nonFiniteSamples += value == SampleValue::NonFinite;
    negativeSamples += value == SampleValue::Negative;
  }
  // Adds the counts of a part of the same render (a chunk of units, a pass); not its seconds.
  void add(const RenderStatistics& part) {
    samples += part.samples;
    vertices += part.vertices;
    nonFiniteSamples += part.nonFiniteSamples;
    negativeSamples += part.negativeSamples;
  }
};

struct RenderResult {
  Image color, albedo, normal, variance;  // the last three empty unless requested
  RenderStatistics statistics;
};

// `progress` (may be empty) hears the fraction of the work done, from worker threads. Settings
// outside the limits above, or spp < 1, throw std::invalid_argument; so do a scene the
// estimator cannot render (a subsurface material for any but the path tracer) and a layer it
// has none of (SPPM's variance), with a message that names it.
RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const std::function<void(double)>& progress = {});

}  // namespace scatterlab
