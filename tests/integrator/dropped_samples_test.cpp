// Nothing fails silently in the estimators that splat (light tracing, BDPT: splat_film.h) or map
// photons (SPPM): a sample whose weight or value is not finite or has a negative channel is
// dropped by the film's rule (sample_value.h) and counted by its kind (render.h
// RenderStatistics), as the path tracer does, and no such value reaches an image.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "render_test_support.h"
#include "tests/validation/test_models.h"

namespace scatterlab {
namespace dropped_samples_test {

using namespace render_test;

const IntegratorKind SplattingAndPhotonEstimators[] = {IntegratorKind::Light, IntegratorKind::Bdpt,
                                                       IntegratorKind::Sppm};

// A Lambertian whose sampled weight is broken on half of its samples, the way the CLI's test
// hook breaks every BSDF (integrator/fault_injection.h): NaN, or -1 per channel.
std::unique_ptr<BsdfModel> faultyLambertian(SampleValue fault) {
  return std::make_unique<test_models::FaultyWeightLambertian>(
      0.5, fault == SampleValue::NonFinite ? Rgb(std::numeric_limits<double>::quiet_NaN()) : Rgb(-1.0));
}

// The faulty sphere on the checkered ground under a sky and the light: light paths reach the
// sphere from both, and camera rays meet it directly.
RenderResult renderFaulty(IntegratorKind kind, SampleValue fault) {
  const Scene scene = makePresetScene(ScenePreset::Preview, faultyLambertian(fault),
                                      Environment::fromMap(smoothSkyMap(16)), 24, 18);
  RenderSettings settings = settingsWith(4, 3, kind != IntegratorKind::Sppm);
  settings.integratorKind = kind;
  settings.albedoLayer = true;
  return render(scene, settings);
}

// Every pixel of every layer finite and without a negative channel.
void expectCleanImage(const Image& image) {
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgb v = image.rgb(x, y);
      ASSERT_TRUE(isFinite(v)) << "pixel (" << x << ", " << y << ")";
      ASSERT_GE(std::min({v.x, v.y, v.z}), 0.0) << "pixel (" << x << ", " << y << ")";
    }
}

TEST(DroppedSamples, NonFiniteWeightsAreCountedAsNonFiniteAndReachNoPixel) {
  for (const IntegratorKind kind : SplattingAndPhotonEstimators) {
    SCOPED_TRACE(toString(kind));
    const RenderResult result = renderFaulty(kind, SampleValue::NonFinite);
    EXPECT_GT(result.statistics.nonFiniteSamples, 0u);
    EXPECT_EQ(result.statistics.negativeSamples, 0u);
    expectCleanImage(result.color);
    expectCleanImage(result.albedo);
    if (!result.variance.empty()) expectCleanImage(result.variance);
  }
}

TEST(DroppedSamples, NegativeWeightsAreCountedAsNegativeAndReachNoPixel) {
  for (const IntegratorKind kind : SplattingAndPhotonEstimators) {
    SCOPED_TRACE(toString(kind));
    const RenderResult result = renderFaulty(kind, SampleValue::Negative);
    EXPECT_GT(result.statistics.negativeSamples, 0u);
    EXPECT_EQ(result.statistics.nonFiniteSamples, 0u);
    expectCleanImage(result.color);
    expectCleanImage(result.albedo);
    if (!result.variance.empty()) expectCleanImage(result.variance);
  }
}

}  // namespace dropped_samples_test
}  // namespace scatterlab
