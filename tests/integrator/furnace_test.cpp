// The white furnace (docs/validation.md section 7): under a constant white environment a sphere of
// a lossless material reflects (or passes) everything, so every pixel of the image, sphere or
// not, is 1 within noise, and the background is exactly 1. And a diffuse sphere under a
// uniform colour renders albedo x colour.
//
// "Within noise": each pixel's mean over n = 128 samples is compared with the expected value
// using the film's variance layer (the variance of the pixel mean, s^2 / n), taken as the
// larger of the pixel's own estimate and its 3 x 3 neighbourhood's mean (robustPixelVariance:
// glossy lobes under MIS give skewed per-sample values whose 128-sample variance estimate is
// sometimes too small). A Gaussian error beyond 5 sigma has probability 6e-7, so over the
// ~6,000 pixels of these tests a false failure has odds below 1%, and the seeds are fixed.
// Models that are lossless only to a known accuracy (a tabulated compensation: its
// BsdfModel::losslessAccuracy()) get that accuracy added to the tolerance. The cases are every
// lossless example the registry's models declare.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include "integrator/silhouette_mask.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "materials/registry/model_list.h"
#include "render_test_support.h"

namespace scatterlab {
namespace furnace_test {

using nlohmann::json;
using namespace render_test;

constexpr double Sigmas = 5.0;

struct LosslessCase {
  std::string name;
  json material;
};

// Every lossless example the registry's models declare (MaterialModel::losslessExamples): a
// model that becomes lossless is tested here without a hand-kept list.
std::vector<LosslessCase> losslessCatalog() {
  std::vector<LosslessCase> cases;
  for (const MaterialModel& model : materialModels())
    for (size_t i = 0; i < model.losslessExamples.size(); ++i) {
      std::string name = model.type;
      if (model.losslessExamples.size() > 1) {
        name += '-';
        name += std::to_string(i + 1);
      }
      cases.push_back({name, model.losslessExamples[i]});
    }
  return cases;
}

// Every sample exactly 1: a sampler whose weight is 1 wherever it samples (smooth glass, a
// perfect mirror, a white Lambertian, which under MIS the constant environment leaves to BSDF
// sampling alone). Then each pixel must be 1 to float precision, which catches a single lost
// path among thousands (a ray that drifts off a glass sphere after many internal reflections,
// say). Probed on 4096 random (wi, u) of a fixed seed, from both sides.
bool samplesWeightOne(const BsdfModel& model) {
  CounterRng rng(7, 0);
  for (int i = 0; i < 4096; ++i) {
    const Vec3d wi = sampleUniformSphere(rng.uniform2D());
    const double uLobe = rng.uniform();
    const auto s = model.sample(wi, uLobe, rng.uniform2D());
    if (s && (std::abs(s->weight.x - 1.0) > 1e-12 || std::abs(s->weight.y - 1.0) > 1e-12 ||
              std::abs(s->weight.z - 1.0) > 1e-12))
      return false;
  }
  return true;
}

class Furnace : public ::testing::TestWithParam<LosslessCase> {};

TEST_P(Furnace, EveryPixelIsOne) {
  const LosslessCase& c = GetParam();
  const std::unique_ptr<BsdfModel> model = makeBsdf(c.material);
  ASSERT_TRUE(model->isLossless()) << c.material.dump() << " is not lossless by its own account";
  // How far from lossless the model itself is allowed to be (a table's error, bsdf.h).
  const double modelTolerance = model->losslessAccuracy();
  const bool exact = samplesWeightOne(*model);
  const Scene scene = sphereScene(c.material, Environment::constant(Rgb(1.0)), 32);
  RenderSettings settings = settingsWith(128, 17);
  // A depth limit loses the light of paths still inside after it (grazing entries into glass
  // bounce near the critical angle): deep enough here that the loss is far below the noise.
  settings.integrator.maxDepth = 200;
  const RenderResult result = render(scene, settings);
  const SilhouetteMask mask = silhouetteMask(scene.camera(), presetSphere());
  double sum = 0.0, variance = 0.0;
  int failures = 0, spherePixels = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const Rgb value = result.color.rgb(x, y), var = robustPixelVariance(result.variance, x, y);
      if (mask.at(x, y) == PixelRegion::Background) {
        EXPECT_EQ(value, Rgb(1.0)) << "background pixel " << x << ", " << y;
        continue;
      }
      spherePixels += mask.at(x, y) == PixelRegion::Sphere;
      for (int k = 0; k < 3; ++k) {
        sum += value[k];
        variance += result.variance.rgb(x, y)[k];
        const double tolerance = exact ? 1e-6 : Sigmas * std::sqrt(var[k]) + modelTolerance + 1e-6;
        if (std::abs(value[k] - 1.0) > tolerance && ++failures <= 5)
          ADD_FAILURE() << "pixel " << x << ", " << y << " channel " << k << ": " << value[k] << " +- "
                        << std::sqrt(var[k]);
      }
    }
  EXPECT_GT(spherePixels, 100);
  EXPECT_EQ(failures, 0);
  // All non-background pixels together: their mean is 1 within 5 standard errors.
  const int count =
      3 * (32 * 32 - int(std::count(mask.regions.begin(), mask.regions.end(), PixelRegion::Background)));
  const double mean = sum / count, error = std::sqrt(variance) / count;
  EXPECT_NEAR(mean, 1.0, Sigmas * error + modelTolerance) << "standard error " << error;
  EXPECT_EQ(result.statistics.droppedSamples(), 0u);
  std::cout << "[ furnace  ] " << c.name << ": mean " << mean << " +- " << error << "\n";
}

INSTANTIATE_TEST_SUITE_P(Catalog, Furnace, ::testing::ValuesIn(losslessCatalog()),
                         [](const ::testing::TestParamInfo<LosslessCase>& info) {
                           std::string name = info.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// A Lambertian sphere of albedo a under a constant colour c renders a c on every sphere pixel
// (a convex sphere sees only the environment), and the background is c exactly.
TEST(UniformEnvironment, DiffuseSphereRendersAlbedoTimesColour) {
  const Rgb albedo(0.7, 0.5, 0.3), colour(0.5, 1.0, 2.0);
  const Scene scene = sphereScene({{"type", "lambertian"}, {"albedo", {albedo.x, albedo.y, albedo.z}}},
                                  Environment::constant(colour), 32);
  const RenderResult result = render(scene, settingsWith(128, 23));
  const SilhouetteMask mask = silhouetteMask(scene.camera(), presetSphere());
  int sphere = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const Rgb value = result.color.rgb(x, y), var = robustPixelVariance(result.variance, x, y);
      if (mask.at(x, y) == PixelRegion::Background) {
        EXPECT_EQ(value, colour) << "background pixel " << x << ", " << y;
      } else if (mask.at(x, y) == PixelRegion::Sphere) {
        ++sphere;
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(value[k], albedo[k] * colour[k], Sigmas * std::sqrt(var[k]) + 1e-6)
              << "pixel " << x << ", " << y << " channel " << k;
      }
    }
  EXPECT_GT(sphere, 100);
}

}  // namespace furnace_test
}  // namespace scatterlab
