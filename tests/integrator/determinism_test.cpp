// Same seed, same image, any thread count: pixels own their random numbers (sampler.h) and
// their accumulation order, so 1 and 2 threads give the same bits in every layer; another
// seed gives another image.
#include <gtest/gtest.h>

#include "render_test_support.h"

namespace scatterlab {
namespace determinism_test {

using namespace render_test;

RenderResult renderPreview(int threads, uint64_t seed) {
  // Glass on the checkered ground under a map: long paths through interiors, NEE on the
  // ground, Russian roulette, a Gaussian filter (rejection sampling draws a varying number
  // of random numbers).
  const Scene scene =
      makePresetScene(ScenePreset::Preview, makeBsdf({{"type", "rough-dielectric"}, {"alpha", 0.2}}),
                      Environment::fromMap(smoothSkyMap(16)), 40, 30);
  RenderSettings settings = settingsWith(8, seed);
  settings.threads = threads;
  settings.filter = PixelFilter::gaussian();
  settings.albedoLayer = settings.normalLayer = true;
  return render(scene, settings);
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameBits) {
  const RenderResult one = renderPreview(1, 5), two = renderPreview(2, 5);
  EXPECT_EQ(one.color.data(), two.color.data());
  EXPECT_EQ(one.variance.data(), two.variance.data());
  EXPECT_EQ(one.albedo.data(), two.albedo.data());
  EXPECT_EQ(one.normal.data(), two.normal.data());
  EXPECT_EQ(one.statistics.vertices, two.statistics.vertices);
}

TEST(Determinism, AnotherSeedGivesAnotherImage) {
  const RenderResult a = renderPreview(2, 5), b = renderPreview(2, 6);
  EXPECT_NE(a.color.data(), b.color.data());
}

}  // namespace determinism_test
}  // namespace scatterlab
